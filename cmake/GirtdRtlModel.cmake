# The Verilated RTL and every source that includes its headers, as one
# library per elaboration: the default build's (sim/) and each RTL variant's
# (build/variants/KEY, sim/rtl/rtl_variants.hpp) are defined here alike.
#   target       the library to make
#   sim_target   what it links against (girtd_sim, or the main build's import)
#   hw_generated the folder with this elaboration's girtd_pkg.sv and rtl_build.hpp
function(girtd_add_rtl_model target sim_target hw_generated)
  set(sim ${CMAKE_SOURCE_DIR}/sim)
  add_library(${target} STATIC ${sim}/rtl/backend_rtl.cpp ${sim}/rtl/backend_rtl_traced.cpp ${sim}/dda/dda_rtl.cpp
                               ${sim}/rtl/rtl_build_info.cpp ${sim}/wave/wave_recorder.cpp)
  target_include_directories(${target} PRIVATE ${sim} ${hw_generated})
  target_link_libraries(${target} PUBLIC ${sim_target})
  target_compile_options(${target} PRIVATE -Wno-unused-parameter)  # Verilator runtime headers
  # The DDA alone (regress --dda-only), fast build (no assertions, X -> fast).
  verilate(${target} PREFIX Vdda TOP_MODULE dda
    SOURCES ${GIRTD_DDA_RTL}
    INCLUDE_DIRS ${hw_generated}
    VERILATOR_ARGS -O3 --x-assign fast --x-initial fast --no-assert --no-timing -Wall)
  # The whole back end; assertions stay on (a FIFO overflow stops the run).
  set(backend_args -O3 --x-assign fast --x-initial fast --assert --no-timing -Wall)
  verilate(${target} PREFIX Vgirtd_backend TOP_MODULE girtd_backend
    SOURCES ${GIRTD_BACKEND_RTL}
    INCLUDE_DIRS ${hw_generated}
    VERILATOR_ARGS ${backend_args})
  # The same back end with FST tracing compiled in, used only for --wave: a run
  # without a waveform keeps the untraced model and pays nothing for the ability.
  verilate(${target} PREFIX Vgirtd_backend_traced TOP_MODULE girtd_backend TRACE_FST
    SOURCES ${GIRTD_BACKEND_RTL}
    INCLUDE_DIRS ${hw_generated}
    VERILATOR_ARGS ${backend_args})

  # Under --sanitize, Verilator 5.006's FST writer (verilated_fst_c.cpp, which
  # includes GTKWave's fstapi.c) is compiled without UBSan checks about
  # third-party code that works as meant on x86: "null", since GCC 12
  # reports the address of Verilator's thread-local context (Verilated::t_s,
  # read in VerilatedTrace's constructor) as a null pointer, which the address
  # of a thread-local never is; "alignment", since fstapi.c stores varints
  # through unaligned uint32_t pointers on purpose. The waveform tests pass
  # bit-exact without the sanitizer. Nothing of ours is exempted.
  # The trace functions Verilator generates for the traced model load 64-bit
  # values from its 32-bit-aligned trace buffer, and fstapi.c shifts negative
  # values left: both are exempted from "alignment" and "shift" there too.
  # The sanitize sub-build (cmake/SanitizeSubBuild.cmake) sets
  # GIRTD_SANITIZE_VERILATED off: there the C++ that Verilator generates from
  # hw/, and Verilator's runtime, are compiled without the sanitizers and
  # without debug information: a sanitizer there would check Verilator's code
  # generator, not ours. The code of ours around them (models/, sim/, the
  # RTL's wrappers here) stays sanitized, and the RTL is checked otherwise
  # (assertions, X randomization, formal proofs, unit benches).
  if(GIRTD_SANITIZE AND NOT GIRTD_SANITIZE_VERILATED)
    get_target_property(_rtl_sources ${target} SOURCES)
    list(REMOVE_DUPLICATES _rtl_sources)  # each Verilated model lists the runtime's sources
    foreach(_source ${_rtl_sources})
      if(_source MATCHES "/V(dda|girtd_backend)[^/]*\\.cpp$" OR _source MATCHES "^${VERILATOR_ROOT}/include/")
        set_property(SOURCE ${_source} APPEND PROPERTY COMPILE_OPTIONS -fno-sanitize=all -g0)
      endif()
    endforeach()
  elseif(GIRTD_SANITIZE)
    set_source_files_properties(${VERILATOR_ROOT}/include/verilated_fst_c.cpp PROPERTIES
                                COMPILE_OPTIONS "-fno-sanitize=null;-fno-sanitize=alignment;-fno-sanitize=shift")
    get_target_property(_rtl_sources ${target} SOURCES)
    foreach(_source ${_rtl_sources})
      if(_source MATCHES "Vgirtd_backend_traced[^/]*__Trace")
        set_property(SOURCE ${_source} APPEND_STRING PROPERTY COMPILE_FLAGS " -fno-sanitize=alignment,shift")
      endif()
    endforeach()
  endif()
endfunction()
