# The libFuzzer targets (testbench/fuzz) need clang, while the simulator is
# built with the default compiler: they are a sub-build of their own in
# build/fuzz, made with every build, and CTest replays each target's seeds,
# corpus and regression files through it ("fuzz: replay ..."). Campaigns run
# by hand: testbench/fuzz/README.md.
include(ExternalProject)
find_program(GIRTD_CLANGXX NAMES clang++ clang++-14)
if(NOT GIRTD_CLANGXX)
  message(FATAL_ERROR "clang++ not found: the fuzz targets need it (tools/girtd installs it)")
endif()
set(GIRTD_FUZZ_BUILD ${CMAKE_BINARY_DIR}/fuzz)
ExternalProject_Add(girtd_fuzz
  SOURCE_DIR ${CMAKE_SOURCE_DIR}
  BINARY_DIR ${GIRTD_FUZZ_BUILD}
  CMAKE_GENERATOR Ninja
  CMAKE_ARGS -DGIRTD_FUZZ=ON -DCMAKE_CXX_COMPILER=${GIRTD_CLANGXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo
  BUILD_ALWAYS ON
  INSTALL_COMMAND ""
  USES_TERMINAL_BUILD ON)

# Replays: each input once (-runs=0 runs the corpus and stops). A crash, a
# leak or a sanitizer report fails the test.
set(_seeds_trace ${CMAKE_SOURCE_DIR}/traces)
set(_seeds_scene ${CMAKE_SOURCE_DIR}/traces/scenes)
set(_seeds_config ${CMAKE_SOURCE_DIR}/config)
foreach(ext obj off ply stl)
  set(_seeds_${ext} ${CMAKE_SOURCE_DIR}/traces/models)
endforeach()
foreach(target trace scene config obj off ply stl)
  set(_dirs ${_seeds_${target}})
  foreach(kind corpus regressions)
    if(EXISTS ${CMAKE_SOURCE_DIR}/testbench/fuzz/${kind}/${target})
      list(APPEND _dirs ${CMAKE_SOURCE_DIR}/testbench/fuzz/${kind}/${target})
    endif()
  endforeach()
  add_test(NAME "fuzz: replay ${target}" COMMAND ${GIRTD_FUZZ_BUILD}/bin/fuzz_${target} -runs=0 ${_dirs})
  set_tests_properties("fuzz: replay ${target}" PROPERTIES LABELS fuzz
                       FAIL_REGULAR_EXPRESSION "ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:"
                       ENVIRONMENT "LSAN_OPTIONS=suppressions=${CMAKE_SOURCE_DIR}/testbench/fuzz/lsan.supp:print_suppressions=0")
endforeach()
