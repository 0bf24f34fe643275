# tests for the atlas (atlas/, dualhex atlas)

# The pages as data (library level).
dualhex_add_test(test_atlas SOURCES test_atlas.cpp DEPS dualhex::atlas)

# The CLI: output refused without --force, a site written, its counts equal --json's.
dualhex_add_test(test_atlas_cli SOURCES test_atlas_cli.cpp DEPS nlohmann_json::nlohmann_json)
target_compile_definitions(test_atlas_cli PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>")
add_dependencies(test_atlas_cli dualhex)

# The site in headless Chromium (Debian chromium): no console message, canvases drawn,
# counts equal the CLI's --json. Skipped (77) only if chromium is absent. Not in the
# sanitizer build: the browser part needs one run, and the suite runs there too.
if(NOT DUALHEX_SANITIZE)
  find_program(DUALHEX_PYTHON3 NAMES python3 PATHS /usr/bin NO_DEFAULT_PATH)
  add_test(NAME atlas_browser
    COMMAND ${DUALHEX_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/atlas_browser_test.py $<TARGET_FILE:dualhex> /usr/bin/chromium)
  set_tests_properties(atlas_browser PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 300)
endif()
