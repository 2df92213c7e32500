# Turns config/girtd.json (the knobs: widths, formats and timings a
# configuration may set) and config/constants.json (the design's fixed
# constants, each with the reason it cannot change) into C++ headers: one
# embeds both files verbatim (parsed at start-up, models/config/params.cpp),
# one gives the constants as constexpr values. No number is written twice.
function(girtd_generate_config_header json_file constants_file out_header)
  file(READ ${json_file} GIRTD_CONFIG_JSON)
  string(JSON _probe ERROR_VARIABLE _err GET "${GIRTD_CONFIG_JSON}" ep)
  if(_err)
    message(FATAL_ERROR "${json_file}: not valid JSON: ${_err}")
  endif()
  file(READ ${constants_file} GIRTD_CONSTANTS_JSON)
  foreach(pair "SCREEN_WIDTH;screen;width" "SCREEN_HEIGHT;screen;height" "COLOR_OUT_BITS;ep;color;out_bits"
               "T_OUT_BITS;ep;t;out_bits" "Z_OUT_BITS;ep;z;out_bits" "NORM_FRAC_BITS;nf;norm_frac_bits")
    list(POP_FRONT pair name)
    string(JSON value ERROR_VARIABLE _err GET "${GIRTD_CONSTANTS_JSON}" ${pair} value)
    if(_err)
      message(FATAL_ERROR "${constants_file}: ${_err}")
    endif()
    set(GIRTD_${name} ${value})
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${json_file} ${constants_file})
  configure_file(${CMAKE_SOURCE_DIR}/cmake/default_config.hpp.in ${out_header} @ONLY)
  get_filename_component(out_dir ${out_header} DIRECTORY)
  configure_file(${CMAKE_SOURCE_DIR}/cmake/design_constants.hpp.in ${out_dir}/design_constants.hpp @ONLY)
endfunction()

# The SystemVerilog side: girtd_gen_rtl (models/layout/gen_rtl_main.cpp)
# writes the package, the PROM table and rtl_build.hpp from the merged
# configuration, with the same C++ that derives every layout for the models
# (one definition). Verilator runs at configure time (verilate()), so the
# generator is compiled and run here, at configure time; it is compiled again
# only when one of its sources changed.
# GIRTD_RTL_CONFIG: a configuration file merged over config/girtd.json for
# the RTL (an RTL variant's build, sim/rtl/rtl_variants.cpp); empty for the
# default build.
function(girtd_generate_rtl_package out_dir)
  set(src ${CMAKE_SOURCE_DIR}/models)
  set(sources ${src}/layout/gen_rtl_main.cpp ${src}/config/params.cpp ${src}/config/config_layers.cpp
              ${src}/layout/rtl_layout.cpp ${src}/layout/rtl_package.cpp ${src}/fifo/fifo_word.cpp
              ${src}/cache/cache_geometry.cpp ${src}/vram/vram_word.cpp)
  file(GLOB headers ${src}/config/*.hpp ${src}/common/*.hpp ${src}/dda/*.hpp ${src}/layout/*.hpp
                    ${src}/fifo/*.hpp ${src}/cache/*.hpp ${src}/vram/*.hpp)
  set(tool ${CMAKE_BINARY_DIR}/generated/girtd_gen_rtl)
  set(stale FALSE)
  if(NOT EXISTS ${tool})
    set(stale TRUE)
  endif()
  foreach(f ${sources} ${headers} ${CMAKE_BINARY_DIR}/generated/girtd/default_config.hpp
            ${CMAKE_BINARY_DIR}/generated/girtd/design_constants.hpp)
    if(${f} IS_NEWER_THAN ${tool})
      set(stale TRUE)
    endif()
  endforeach()
  if(stale)
    message(STATUS "Compiling girtd_gen_rtl (the RTL package generator)")
    set(launcher "")
    if(CCACHE_PROGRAM)
      set(launcher ${CCACHE_PROGRAM})
    endif()
    execute_process(
      COMMAND ${launcher} ${CMAKE_CXX_COMPILER} -std=c++17 -O1 -I${src} -I${CMAKE_BINARY_DIR}/generated
              ${sources} -o ${tool}
      RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(rc)
      message(FATAL_ERROR "compiling girtd_gen_rtl failed:\n${err}")
    endif()
  endif()
  set(config_args "")
  if(GIRTD_RTL_CONFIG)
    set(config_args --config ${GIRTD_RTL_CONFIG})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${GIRTD_RTL_CONFIG})
  endif()
  execute_process(COMMAND ${tool} ${config_args} ${out_dir} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc)
    message(FATAL_ERROR "girtd_gen_rtl: ${err}")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${sources} ${headers})
endfunction()
