# cmake -P script: install the dualhex build tree into a fresh prefix, then configure,
# build and run tests/consumer against it; the programs run after the prefix has been
# moved, from a directory outside the source tree. Every run starts from empty directories.
# Inputs: DUALHEX_BUILD_DIR, CONSUMER_SOURCE_DIR, WORK_DIR, CXX_COMPILER, BUILD_TYPE,
#         SANITIZE (ON/OFF: the static libraries are instrumented, so the consumer must
#         link the sanitizer runtimes too).
foreach(var DUALHEX_BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_consumer_test.cmake: ${var} not set")
  endif()
endforeach()

set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "consumer test: command failed (${rc}): ${cmd}")
  endif()
endfunction()

run("${CMAKE_COMMAND}" --install "${DUALHEX_BUILD_DIR}" --prefix "${prefix}")

set(flags "")
if(SANITIZE)
  set(flags "-fsanitize=address,undefined")
endif()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
run("${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE_DIR}" -B "${build}"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
    "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_CXX_FLAGS=${flags}"
    "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON")
run("${CMAKE_COMMAND}" --build "${build}")

# From here on the installed tree lives elsewhere (nothing may depend on the install path),
# every program runs in a directory outside the source tree, and DUALHEX_ELEMENTS is unset:
# the elements must come from the libraries themselves.
set(moved "${WORK_DIR}/moved-prefix")
file(RENAME "${prefix}" "${moved}")
set(ENV{DUALHEX_ELEMENTS})
set(run_dir "${WORK_DIR}/run")
file(MAKE_DIRECTORY "${run_dir}")
function(run_outside)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${run_dir}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "consumer test: command failed (${rc}): ${cmd}")
  endif()
endfunction()
run_outside("${build}/consumer")
run_outside("${build}/consumer_all_layers")
run_outside("${build}/consumer_install")

# The README's library example on a two-level paired grid (level 2, the level-1 octant at
# the origin at level 3), written here so no source file is read. Its hex mesh must be
# the installed CLI's, byte for byte.
set(grid "${run_dir}/grid.leaves")
set(text "# level 2; the level-1 octant 0 0 0 at level 3\n")
foreach(i RANGE 3)
  foreach(j RANGE 3)
    foreach(k RANGE 3)
      if(i GREATER 1 OR j GREATER 1 OR k GREATER 1)
        string(APPEND text "2 ${i} ${j} ${k}\n")
      endif()
      string(APPEND text "3 ${i} ${j} ${k}\n")
    endforeach()
  endforeach()
endforeach()
file(WRITE "${grid}" "${text}")
run_outside("${build}/example" "${grid}" "${run_dir}/example.vtk")
run_outside("${moved}/bin/dualhex" install "${grid}" -o "${run_dir}/cli")
file(SHA256 "${run_dir}/example.vtk" example_hash)
file(SHA256 "${run_dir}/cli.hex.vtk" cli_hash)
if(NOT example_hash STREQUAL cli_hash)
  message(FATAL_ERROR "consumer test: the library example's mesh differs from `dualhex install`'s")
endif()

# The installed CLI runs too.
run_outside("${moved}/bin/dualhex" --version)

# ...and find_package found the fresh prefix, not something else on the system.
file(STRINGS "${build}/CMakeCache.txt" dir_line REGEX "^dualhex_DIR:")
string(FIND "${dir_line}" "${prefix}" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "consumer test: find_package(dualhex) did not use ${prefix}: ${dir_line}")
endif()
message(STATUS "consumer test: OK (${dir_line})")
