# The unit and pipeline tests again with ASan and UBSan (label sanitize, in
# `tools/girtd test` and so in CI; testbench/README.md "Sanitizers"): a
# sub-build of just those two executables in build/sanitize, made by target
# girtd_sanitize (a plain build leaves it out) and built by the fixture below
# before they run. Our code is sanitized, the C++ Verilator generates from
# hw/ is not (GIRTD_SANITIZE_VERILATED, cmake/GirtdRtlModel.cmake), and all
# is compiled at -O1 (ASan's recommended level, half the compile time of -O3
# on this code) with line tables only: the sub-build went from 22 minutes on
# 2 cores (-O3 -g, the Verilated RTL sanitized) to what testbench/README.md
# "Sanitizers" gives. It shares build/ with the fuzz sub-build's fixture:
# the two never run at once (RESOURCE_LOCK), as one ninja per folder.
# `tools/girtd test --sanitize` builds and tests everything, the Verilated
# RTL included, that way.
include(ExternalProject)
set(GIRTD_SANITIZE_BUILD ${CMAKE_BINARY_DIR}/sanitize)
ExternalProject_Add(girtd_sanitize
  SOURCE_DIR ${CMAKE_SOURCE_DIR}
  BINARY_DIR ${GIRTD_SANITIZE_BUILD}
  CMAKE_GENERATOR Ninja
  CMAKE_ARGS -DGIRTD_SANITIZE=ON -DGIRTD_SANITIZE_VERILATED=OFF -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG"
  BUILD_COMMAND ${CMAKE_COMMAND} --build <BINARY_DIR> --target girtd_unit_tests girtd_pipeline_tests
  BUILD_ALWAYS ON
  EXCLUDE_FROM_ALL ON
  INSTALL_COMMAND ""
  USES_TERMINAL_BUILD ON)

file(STRINGS ${CMAKE_SOURCE_DIR}/testbench/sanitize/sanitizer.env _sanitizer_env REGEX "^[A-Z_]+=")
string(REPLACE "suppressions=" "suppressions=${CMAKE_SOURCE_DIR}/" _sanitizer_env "${_sanitizer_env}")
add_test(NAME "sanitize: build the unit and pipeline tests"
         COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target girtd_sanitize)
set_tests_properties("sanitize: build the unit and pipeline tests" PROPERTIES
                     FIXTURES_SETUP sanitized_tests LABELS "sanitize" TIMEOUT 3600 RESOURCE_LOCK build_folder)
foreach(suite unit pipeline)
  add_test(NAME "sanitize: ${suite} tests, each case in its own process"
           COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/testbench/sanitize/each_test_case.py
                   ${GIRTD_SANITIZE_BUILD}/bin/girtd_${suite}_tests
           WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties("sanitize: ${suite} tests, each case in its own process" PROPERTIES
                       FIXTURES_REQUIRED sanitized_tests LABELS "sanitize" TIMEOUT 3600
                       ENVIRONMENT "${_sanitizer_env};SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1")
endforeach()
