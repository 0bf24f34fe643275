#pragma once
// Running dualhex-dist under mpirun --oversubscribe from a test (the targets that include
// this define DUALHEX_DIST_EXE and DUALHEX_MPIEXEC), in a scratch directory.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "run_process.hpp"

namespace dualhex::test {

struct Scratch {
    std::filesystem::path dir;
    explicit Scratch(const std::string& name)
        : dir(std::filesystem::temp_directory_path() / ("dualhex_dist_" + name + "_" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    ~Scratch() { std::filesystem::remove_all(dir); }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
};

inline ProcessResult run_dist(int np, const std::vector<std::string>& args, const std::filesystem::path& scratch) {
    // Open MPI refuses root without these (CI runs as root); harmless otherwise.
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    std::vector<std::string> full{"--oversubscribe", "-np", std::to_string(np), DUALHEX_DIST_EXE};
    full.insert(full.end(), args.begin(), args.end());
    return run_process(DUALHEX_MPIEXEC, full, scratch);
}

}  // namespace dualhex::test
