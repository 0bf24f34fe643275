#include "dualhex/checkers/weak_exhaustive.hpp"

#include <algorithm>
#include <chrono>
#include <set>

#include <tbb/parallel_for.h>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/grid/configurations.hpp"

namespace dualhex {

std::vector<LevelAssignment> weak_configurations() {
    std::vector<LevelAssignment> out;
    for (int code = 0; code < 6561; ++code) {  // 3^8
        LevelAssignment lv{};
        int c = code;
        for (auto& l : lv) {
            l = static_cast<std::uint8_t>(c % 3);
            c /= 3;
        }
        if (*std::min_element(lv.begin(), lv.end()) != 0) continue;
        bool balanced = true;
        for (int b = 0; b < 8 && balanced; ++b)
            for (int a = 0; a < 3; ++a)
                if (std::abs(int(lv[b]) - int(lv[b ^ (1 << a)])) > 1) balanced = false;
        if (balanced) out.push_back(lv);
    }
    return out;
}

std::function<int(int, int, int)> torus_levels(const LevelAssignment& levels) {
    return [levels](int x, int y, int z) { return int(levels[(x & 1) | ((y & 1) << 1) | ((z & 1) << 2)]); };
}

LevelAssignment canonical(const LevelAssignment& levels) {
    // As two masks (level >= 1, level >= 2), each moved by grid's action on octant masks.
    ConfigMask at_least[2] = {0, 0};
    for (int b = 0; b < 8; ++b)
        for (int t = 0; t < 2; ++t)
            if (levels[b] > t) at_least[t] = static_cast<ConfigMask>(at_least[t] | (1u << b));
    LevelAssignment best{3, 3, 3, 3, 3, 3, 3, 3};
    for (const CubeSymmetry& g : group_elements(SymmetryGroup::Full)) {
        const ConfigMask m1 = apply(g, at_least[0]), m2 = apply(g, at_least[1]);
        LevelAssignment image{};
        for (int b = 0; b < 8; ++b) image[b] = static_cast<std::uint8_t>(((m1 >> b) & 1) + ((m2 >> b) & 1));
        best = std::min(best, image);
    }
    return best;
}

WeakExhaustiveResult run_weak_exhaustive(const TransitionRule& rule, const ElementLibrary& library) {
    const auto t0 = std::chrono::steady_clock::now();
    WeakExhaustiveResult r;
    const std::vector<LevelAssignment> configurations = weak_configurations();
    // Each configuration's torus and window are independent: checked in parallel, then
    // tallied in configuration order (the same result for any thread count).
    std::vector<ConfigurationReport> tori(configurations.size()), windows(configurations.size());
    tbb::parallel_for(std::size_t{0}, configurations.size(), [&](std::size_t n) {
        const LevelAssignment& lv = configurations[n];
        tori[n] = check_periodic_levels(torus_levels(lv), 2, rule, library);
        std::array<int, 8> levels{};
        for (int b = 0; b < 8; ++b) levels[static_cast<std::size_t>(b)] = lv[static_cast<std::size_t>(b)];
        windows[n] = check_window_levels(levels, rule, library);
    });
    std::set<LevelAssignment> classes, three;
    for (std::size_t n = 0; n < configurations.size(); ++n) {
        const LevelAssignment& lv = configurations[n];
        ++r.configurations;
        const LevelAssignment key = canonical(lv);
        classes.insert(key);
        if (*std::max_element(lv.begin(), lv.end()) == 2) three.insert(key);
        const ConfigurationReport& report = tori[n];
        const ConfigurationReport& window = windows[n];
        r.periodic_passed += report.ok();
        r.window_passed += window.ok();
        if (report.ok() && window.ok())
            ++r.passed;
        else
            r.failures.push_back((report.ok() ? "window " + window.summary() : "torus " + report.summary()));
        for (const auto& [name, count] : report.elements) r.elements[name] += count;
        if (!report.dual_edge_valences.empty())
            r.max_dual_edge_valence = std::max(r.max_dual_edge_valence, report.dual_edge_valences.rbegin()->first);
    }
    r.classes = static_cast<int>(classes.size());
    r.three_level_classes = static_cast<int>(three.size());
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

}  // namespace dualhex
