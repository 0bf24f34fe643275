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

# The terminal progress bar (apps/progress_bar.cpp) on a fake clock and a string stream.
dualhex_add_test(test_apps_progress_bar SOURCES test_apps_progress_bar.cpp ${PROJECT_SOURCE_DIR}/apps/progress_bar.cpp
                 DEPS dualhex::topology CLI11::CLI11)
target_include_directories(test_apps_progress_bar PRIVATE ${PROJECT_SOURCE_DIR}/apps)

# The bar in a real terminal (tmux): seen while `dualhex mesh` runs, replaced by the summary;
# nothing of it with stderr redirected to a file or under --json. Skipped (77) only without tmux.
foreach(mode bar redirect)
  add_test(NAME progress_tmux_${mode}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/progress_tmux_test.sh $<TARGET_FILE:dualhex>
            ${CMAKE_CURRENT_BINARY_DIR}/progress-tmux-${mode} ${mode})
  set_tests_properties(progress_tmux_${mode} PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 900)
endforeach()
