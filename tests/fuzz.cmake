# libFuzzer harnesses of the readers (tests/fuzz/fuzz_<reader>.cpp), compiled by clang with
# -fsanitize=fuzzer,address,undefined directly from the reader sources (the libraries are
# built by the project's compiler, usually g++, which has no libFuzzer). Built only when
# clang++ can link a fuzzer here (checked at configure time); each has a bounded CTest run
# (DUALHEX_FUZZ_SECONDS) over a seed corpus: tests/fuzz/seeds/<reader> and the small files
# (< 64 KiB) of the shared data. bench/run_fuzz_readers.sh runs them longer.
option(DUALHEX_FUZZ "Build the libFuzzer harnesses of the readers if clang++ supports -fsanitize=fuzzer" ON)
set(DUALHEX_FUZZ_SECONDS 15 CACHE STRING "Seconds each fuzz_* CTest run fuzzes")

set(DUALHEX_FUZZ_FLAGS -std=c++20 -O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer,address,undefined
                       -fno-sanitize-recover=undefined)
set(dualhex_fuzz_ok FALSE)
if(DUALHEX_FUZZ)
  find_program(DUALHEX_CLANGXX NAMES clang++ clang++-14)
  if(DUALHEX_CLANGXX)
    set(probe_dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz/probe)
    file(MAKE_DIRECTORY ${probe_dir})
    file(WRITE ${probe_dir}/probe.cpp
         "#include <cstddef>\n#include <cstdint>\nextern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
    execute_process(COMMAND ${DUALHEX_CLANGXX} ${DUALHEX_FUZZ_FLAGS} probe.cpp -o probe
                    WORKING_DIRECTORY ${probe_dir} RESULT_VARIABLE probe_rc OUTPUT_QUIET ERROR_QUIET)
    if(probe_rc EQUAL 0)
      set(dualhex_fuzz_ok TRUE)
    endif()
  endif()
  if(NOT dualhex_fuzz_ok)
    message(STATUS "dualhex: no clang++ with -fsanitize=fuzzer (Debian: clang, libfuzzer-14-dev); fuzz harnesses not built")
  endif()
endif()

if(dualhex_fuzz_ok)
  find_program(DUALHEX_FUZZ_CCACHE ccache)
  find_path(DUALHEX_EIGEN_INCLUDE Eigen/Core PATHS /usr/include/eigen3 PATH_SUFFIXES eigen3)
  set(fuzz_includes -I${PROJECT_SOURCE_DIR}/geometry/include -I${PROJECT_SOURCE_DIR}/geometry/src
                    -I${PROJECT_SOURCE_DIR}/grid/include -I${PROJECT_SOURCE_DIR}/topology/include
                    -I${DUALHEX_EIGEN_INCLUDE})
  set(fuzz_obj_dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz/obj)
  file(MAKE_DIRECTORY ${fuzz_obj_dir})

  # One clang object per source, shared by the harnesses that need it.
  function(dualhex_fuzz_object src out_var)
    get_filename_component(name ${src} NAME_WE)
    get_filename_component(layer_dir ${src} DIRECTORY)
    get_filename_component(layer_dir ${layer_dir} DIRECTORY)
    get_filename_component(layer ${layer_dir} NAME)
    set(obj ${fuzz_obj_dir}/${layer}_${name}.o)
    add_custom_command(OUTPUT ${obj}
      COMMAND ${DUALHEX_FUZZ_CCACHE} ${DUALHEX_CLANGXX} ${DUALHEX_FUZZ_FLAGS} ${fuzz_includes} -c ${src} -o ${obj}
      DEPENDS ${src} IMPLICIT_DEPENDS CXX ${src}
      COMMENT "clang (fuzz) ${layer}/${name}.cpp" VERBATIM)
    set(${out_var} ${obj} PARENT_SCOPE)
  endfunction()

  set(surface_sources surface_parse read_obj read_off read_stl read_ply surface self_intersection exact_predicates
                      aabb_tree triangle_geometry)
  set(surface_objects)
  foreach(s ${surface_sources})
    dualhex_fuzz_object(${PROJECT_SOURCE_DIR}/geometry/src/${s}.cpp obj)
    list(APPEND surface_objects ${obj})
  endforeach()
  set(leaves_objects)
  foreach(s input_error leaf leaf_grid leaf_file)
    dualhex_fuzz_object(${PROJECT_SOURCE_DIR}/grid/src/${s}.cpp obj)
    list(APPEND leaves_objects ${obj})
  endforeach()
  find_library(DUALHEX_FUZZ_GMPXX gmpxx)
  find_library(DUALHEX_FUZZ_GMP gmp)
  # The leaf grid's checks and the surface tree's batched queries run in parallel (oneTBB).
  find_library(DUALHEX_FUZZ_TBB tbb)

  # Seeds: the harness's own (tests/fuzz/seeds/<reader>) and the small shared files.
  file(GLOB shared_small ${DUALHEX_SHARED_DATA}/surfaces/* ${DUALHEX_SHARED_DATA}/grids/*)
  foreach(reader obj off stl ply leaves)
    set(fuzz_dir ${CMAKE_CURRENT_BINARY_DIR}/fuzz/${reader})
    file(MAKE_DIRECTORY ${fuzz_dir}/seeds ${fuzz_dir}/corpus)
    file(GLOB own_seeds ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/seeds/${reader}/*)
    file(COPY ${own_seeds} DESTINATION ${fuzz_dir}/seeds)
    foreach(f ${shared_small})
      file(SIZE ${f} bytes)
      if(f MATCHES "\\.${reader}$" AND bytes LESS 65536)
        file(COPY ${f} DESTINATION ${fuzz_dir}/seeds)
      endif()
    endforeach()

    if(reader STREQUAL "leaves")
      set(objects ${leaves_objects})
      set(libs ${DUALHEX_FUZZ_TBB})
    else()
      set(objects ${surface_objects})
      set(libs ${DUALHEX_FUZZ_GMPXX} ${DUALHEX_FUZZ_GMP} ${DUALHEX_FUZZ_TBB})
    endif()
    set(harness_src ${CMAKE_CURRENT_SOURCE_DIR}/fuzz/fuzz_${reader}.cpp)
    dualhex_fuzz_object(${harness_src} harness_obj)
    set(exe ${CMAKE_CURRENT_BINARY_DIR}/fuzz/fuzz_${reader})
    add_custom_command(OUTPUT ${exe}
      COMMAND ${DUALHEX_CLANGXX} ${DUALHEX_FUZZ_FLAGS} ${harness_obj} ${objects} ${libs} -o ${exe}
      DEPENDS ${harness_obj} ${objects} COMMENT "clang (fuzz) link fuzz_${reader}" VERBATIM)
    add_custom_target(fuzz_${reader} ALL DEPENDS ${exe})
    # New inputs go to corpus/ (in the build tree); crashes to fuzz_dir, named crash-*.
    add_test(NAME fuzz_${reader}
      COMMAND ${exe} -max_total_time=${DUALHEX_FUZZ_SECONDS} -timeout=10 -rss_limit_mb=2048 -max_len=65536
              -print_final_stats=1 -artifact_prefix=${fuzz_dir}/ ${fuzz_dir}/corpus ${fuzz_dir}/seeds)
    set_tests_properties(fuzz_${reader} PROPERTIES TIMEOUT 120 LABELS fuzz)
  endforeach()
endif()
