# cmake -P script: install the dualhex build tree into a fresh prefix, then configure,
# build and run tests/consumer against it. Every run starts from empty directories.
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
run("${build}/consumer")
run("${build}/consumer_all_layers")
run("${build}/consumer_install")

# The installed CLI runs too.
run("${prefix}/bin/dualhex" --version)

# ...and find_package found the fresh prefix, not something else on the system.
file(STRINGS "${build}/CMakeCache.txt" dir_line REGEX "^dualhex_DIR:")
string(FIND "${dir_line}" "${prefix}" at)
if(NOT at GREATER -1)
  message(FATAL_ERROR "consumer test: find_package(dualhex) did not use ${prefix}: ${dir_line}")
endif()
message(STATUS "consumer test: OK (${dir_line})")
