# tests for the apps layer

# The CLI, run as a process (exit codes, stdout/stderr, files).
dualhex_add_test(test_apps_cli SOURCES test_apps_cli.cpp DEPS nlohmann_json::nlohmann_json)
target_compile_definitions(test_apps_cli PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>")
add_dependencies(test_apps_cli dualhex)

# find_package(dualhex) from an installed tree: install into a fresh prefix, build and run
# tests/consumer against it (tests/consumer/run_consumer_test.cmake).
add_test(NAME consumer_find_package
  COMMAND ${CMAKE_COMMAND}
    -DDUALHEX_BUILD_DIR=${PROJECT_BINARY_DIR}
    -DCONSUMER_SOURCE_DIR=${CMAKE_CURRENT_SOURCE_DIR}/consumer
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer-work
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
    -DSANITIZE=${DUALHEX_SANITIZE}
    -P ${CMAKE_CURRENT_SOURCE_DIR}/consumer/run_consumer_test.cmake)
set_tests_properties(consumer_find_package PROPERTIES TIMEOUT 300 RUN_SERIAL FALSE)

# The CLI against hostile inputs and outputs (issue 15), run as a process.
dualhex_add_test(test_apps_hostile SOURCES test_apps_hostile.cpp DEPS nlohmann_json::nlohmann_json)
target_compile_definitions(test_apps_hostile PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>")
add_dependencies(test_apps_hostile dualhex)
