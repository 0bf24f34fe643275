# tests for distributed/: the canonical summary (MIT, every build, sanitizers included) and,
# with DUALHEX_WITH_P4EST (OFF by default under the sanitizers: LeakSanitizer reports Open
# MPI's own allocations), dualhex-dist under mpirun -np 1..4.
dualhex_add_test(test_canonical SOURCES test_canonical.cpp DEPS dualhex::canonical)

if(DUALHEX_WITH_P4EST)
  dualhex_add_test(test_distributed SOURCES test_distributed.cpp DEPS dualhex::canonical nlohmann_json::nlohmann_json)
  target_compile_definitions(test_distributed PRIVATE DUALHEX_DIST_EXE="$<TARGET_FILE:dualhex-dist>"
                                                      DUALHEX_MPIEXEC="${MPIEXEC_EXECUTABLE}")
  add_dependencies(test_distributed dualhex-dist)
  dualhex_add_test(test_distributed_reader SOURCES test_distributed_reader.cpp DEPS dualhex::canonical nlohmann_json::nlohmann_json)
  dualhex_add_test(test_distributed_surface SOURCES test_distributed_surface.cpp
                   DEPS dualhex::canonical dualhex::mesher nlohmann_json::nlohmann_json)
  foreach(t test_distributed_reader test_distributed_surface)
    target_compile_definitions(${t} PRIVATE DUALHEX_DIST_EXE="$<TARGET_FILE:dualhex-dist>"
                                            DUALHEX_MPIEXEC="${MPIEXEC_EXECUTABLE}")
    add_dependencies(${t} dualhex-dist)
  endforeach()
endif()
