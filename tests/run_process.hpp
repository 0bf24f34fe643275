#pragma once
// Running a built executable as a process from a test: stdout and stderr captured through
// files in a scratch directory, stdin closed, the exit code decoded.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace dualhex::test {

struct ProcessResult {
    int rc = -1;  ///< exit code, or 128 + signal
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// Single-quoted for /bin/sh.
inline std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// Runs `exe args...` with stdout/stderr in `scratch`/stdout and `scratch`/stderr.
inline ProcessResult run_process(const std::string& exe, const std::vector<std::string>& args,
                                 const std::filesystem::path& scratch) {
    std::string cmd = shell_quote(exe);
    for (const auto& a : args) {
        cmd += ' ';
        cmd += shell_quote(a);
    }
    // (appended piecewise: `" >" + std::string` trips GCC 12's -Wrestrict false positive)
    cmd += " >";
    cmd += shell_quote((scratch / "stdout").string());
    cmd += " 2>";
    cmd += shell_quote((scratch / "stderr").string());
    cmd += " </dev/null";
    const int status = std::system(cmd.c_str());
    ProcessResult r;
    r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(scratch / "stdout");
    r.err = slurp(scratch / "stderr");
    return r;
}

}  // namespace dualhex::test
