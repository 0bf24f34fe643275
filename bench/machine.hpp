#pragma once
// The machine a benchmark ran on, for its table header (figures are only meaningful with it).
#include <fstream>
#include <string>

namespace dualhex::bench {

/// The CPU model from /proc/cpuinfo ("unknown" elsewhere).
inline std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown";
}

}  // namespace dualhex::bench
