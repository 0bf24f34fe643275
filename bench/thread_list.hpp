#pragma once
// The thread counts a scaling benchmark runs, from its --threads option ("1,2,4").
#include <cstdlib>
#include <vector>

namespace dualhex::bench {

/// "1,2,4" -> {1, 2, 4}.
inline std::vector<int> parse_thread_list(const char* text) {
    std::vector<int> out;
    for (const char* p = text; *p;) {
        out.push_back(std::atoi(p));
        while (*p && *p != ',') ++p;
        if (*p == ',') ++p;
    }
    return out;
}

}  // namespace dualhex::bench
