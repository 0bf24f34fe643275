# tests for the install layer: installation into grids, the clipped dual, `dualhex install`,
# random-grid properties
dualhex_add_test(test_install SOURCES test_install.cpp DEPS dualhex::install)
dualhex_add_test(test_install_clipped_dual SOURCES test_install_clipped_dual.cpp DEPS dualhex::install)

# `dualhex install` as a process
dualhex_add_test(test_install_cli SOURCES test_install_cli.cpp DEPS nlohmann_json::nlohmann_json)
target_compile_definitions(test_install_cli PRIVATE DUALHEX_EXE="$<TARGET_FILE:dualhex>"
                                                   DUALHEX_PROOF_CHECKER="$<TARGET_FILE:dualhex-proof-checker>")
add_dependencies(test_install_cli dualhex dualhex-proof-checker)

# random grids through the whole pipeline (RapidCheck)
dualhex_add_test(test_install_properties SOURCES test_install_properties.cpp DEPS dualhex::install)

# bit-identical results for 1..4 threads (oneTBB task arenas): install, clipped dual, files
dualhex_add_test(test_install_threads SOURCES test_install_threads.cpp DEPS dualhex::install dualhex::geometry)

# install_leaves / leaf_context with a query: a subset of leaves with supplied contexts
dualhex_add_test(test_install_subset SOURCES test_install_subset.cpp DEPS dualhex::install)
