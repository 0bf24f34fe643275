#pragma once
// Shared by the proofs tests: the shipped certificates, file helpers, running the
// standalone checker (DUALHEX_PROOF_CHECKER) and splitting a file into certificates.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace dualhex {
namespace {

namespace fs = std::filesystem;

inline const fs::path kShipped = fs::path(DUALHEX_SOURCE_DIR) / "proofs" / "certificates";

inline std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
inline void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

inline fs::path temp_dir(const std::string& tag) {
    const fs::path d = fs::temp_directory_path() / ("dualhex-proofs-" + tag + "-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

struct CheckerRun {
    int code = -1;
    std::string out;
};
inline CheckerRun run_checker(const std::string& args) {
    CheckerRun r;
    FILE* p = ::popen((std::string(DUALHEX_PROOF_CHECKER) + " " + args + " 2>&1").c_str(), "r");
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, p)) r.out.append(buf, n);
    const int status = ::pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline std::vector<std::string> split_certificates(const std::string& text) {
    std::vector<std::string> out;
    std::size_t at = 0;
    while ((at = text.find("dualhex-certificate 2\n", at)) != std::string::npos) {
        const std::size_t end = text.find("\nend\n", at);
        out.push_back(text.substr(at, end + 5 - at));
        at = end;
    }
    return out;
}

}  // namespace
}  // namespace dualhex
