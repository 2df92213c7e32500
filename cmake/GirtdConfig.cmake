# Turns config/girtd.json (the single description of widths, formats and
# timings) into a C++ header that embeds it verbatim. The C++ side parses the
# embedded text at start-up (models/config/params.cpp), so no number is ever
# written twice. The SystemVerilog package will be generated here too.
function(girtd_generate_config_header json_file out_header)
  file(READ ${json_file} GIRTD_CONFIG_JSON)
  string(JSON _probe ERROR_VARIABLE _err GET "${GIRTD_CONFIG_JSON}" ep)
  if(_err)
    message(FATAL_ERROR "${json_file}: not valid JSON: ${_err}")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${json_file})
  configure_file(${CMAKE_SOURCE_DIR}/cmake/default_config.hpp.in ${out_header} @ONLY)
endfunction()
