# The libFuzzer targets (testbench/fuzz) need clang, while the simulator is
# built with the default compiler: they are a sub-build of their own in
# build/fuzz, made by target girtd_fuzz (a plain build leaves it out, so
# demo users do not wait for it; CTest's fixture and tools/girtd fuzz build
# it), and CTest replays each target's seeds,
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
  EXCLUDE_FROM_ALL ON
  INSTALL_COMMAND ""
  USES_TERMINAL_BUILD ON)

# Replays: each input once (-runs=0 runs the corpus and stops). A crash, a
# leak or a sanitizer report fails the test. The fixture builds the targets
# first, so a plain ctest never replays a missing or stale binary.
add_test(NAME "fuzz: build the targets" COMMAND ${CMAKE_COMMAND} --build ${CMAKE_BINARY_DIR} --target girtd_fuzz)
# One ninja at a time in build/: the sanitize sub-build's fixture takes the same lock.
set_tests_properties("fuzz: build the targets" PROPERTIES FIXTURES_SETUP fuzz_targets LABELS fuzz RESOURCE_LOCK build_folder)
set(_seeds_trace ${CMAKE_SOURCE_DIR}/traces)
set(_seeds_scene ${CMAKE_SOURCE_DIR}/traces/scenes)
set(_seeds_config ${CMAKE_SOURCE_DIR}/config)
set(_seeds_sweep_spec ${CMAKE_SOURCE_DIR}/traces/sweeps)
foreach(ext obj off ply stl)
  set(_seeds_${ext} ${CMAKE_SOURCE_DIR}/traces/models)
endforeach()
# glTF and Collada: the repo's scenes in model files, and assimp's own test
# models where they are installed (assimp-testmodels, a test dependency).
set(_seeds_gltf ${CMAKE_SOURCE_DIR}/traces/models/file_scenes)
set(_seeds_dae)
foreach(pair "gltf;glTF2" "dae;Collada")
  list(GET pair 0 ext)
  list(GET pair 1 folder)
  if(EXISTS /usr/share/assimp/models/${folder})
    list(APPEND _seeds_${ext} /usr/share/assimp/models/${folder})
  endif()
endforeach()
foreach(target trace scene config sweep_spec obj off ply stl gltf dae)
  set(_dirs ${_seeds_${target}})
  if(NOT _dirs)
    continue()  # no seeds on this machine
  endif()
  foreach(kind corpus regressions)
    if(EXISTS ${CMAKE_SOURCE_DIR}/testbench/fuzz/${kind}/${target})
      list(APPEND _dirs ${CMAKE_SOURCE_DIR}/testbench/fuzz/${kind}/${target})
    endif()
  endforeach()
  add_test(NAME "fuzz: replay ${target}" COMMAND ${GIRTD_FUZZ_BUILD}/bin/fuzz_${target} -runs=0 ${_dirs})
  set_tests_properties("fuzz: replay ${target}" PROPERTIES LABELS fuzz FIXTURES_REQUIRED fuzz_targets
                       FAIL_REGULAR_EXPRESSION "ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:")
  # No pre-check stands between assimp's glTF and Collada readers and their
  # own leak on refused input (glTF's checks only its buffers' bounds), so
  # their replays pass over that leak as campaigns do (testbench/fuzz/README.md
  # "Findings"); the other targets' replays never.
  if(target STREQUAL "gltf" OR target STREQUAL "dae")
    set_tests_properties("fuzz: replay ${target}" PROPERTIES ENVIRONMENT
                         "LSAN_OPTIONS=suppressions=${CMAKE_SOURCE_DIR}/testbench/fuzz/assimp_leaks.supp")
  endif()
endforeach()
