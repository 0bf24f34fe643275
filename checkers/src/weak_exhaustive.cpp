#include "dualhex/checkers/weak_exhaustive.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/torus_classes.hpp"
#include "dualhex/grid/configurations.hpp"
#include "dualhex/install/element_templates.hpp"
#include "congruence_check.hpp"
#include "window_check.hpp"

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

namespace {

// The assignment moved by a window symmetry (octant b is on the + side of axis a iff bit a)
// or by a torus motion (congruence_check.hpp checks the configurations class by class).
LevelAssignment moved_by(const LevelAssignment& lv, const CubeSymmetry& s) {
    LevelAssignment out{};
    for (int b = 0; b < 8; ++b) {
        const LatticePoint img = s.apply({b & 1 ? 1 : -1, b & 2 ? 1 : -1, b & 4 ? 1 : -1});
        out[static_cast<std::size_t>((img.x > 0) | (img.y > 0) << 1 | (img.z > 0) << 2)] = lv[static_cast<std::size_t>(b)];
    }
    return out;
}
LevelAssignment moved_by(const LevelAssignment& lv, const TorusMotion& m) {
    LevelAssignment out{};
    for (int b = 0; b < 8; ++b) out[static_cast<std::size_t>(m.apply_octant(b))] = lv[static_cast<std::size_t>(b)];
    return out;
}

}  // namespace

WeakExhaustiveResult run_weak_exhaustive(const TransitionRule& rule, const ElementLibrary& library) {
    const auto t0 = std::chrono::steady_clock::now();
    WeakExhaustiveResult r;
    const std::vector<LevelAssignment> configurations = weak_configurations();
    const auto as_levels = [](const LevelAssignment& lv) {
        std::array<int, 8> levels{};
        for (int b = 0; b < 8; ++b) levels[static_cast<std::size_t>(b)] = lv[static_cast<std::size_t>(b)];
        return levels;
    };
    const std::int64_t octant = 4 * detail::common_unit(library);
    // One template cache per thread for every build (the templates do not depend on who
    // placed them first): a cache per configuration re-made each template it used.
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    // Tori: classes under the 384 motions of the torus; windows: under the 48 symmetries.
    const auto moved = [](const LevelAssignment& lv, const auto& m) { return moved_by(lv, m); };
    const std::vector<ConfigurationReport> tori = detail::check_by_congruence(
        detail::congruence(configurations, torus_motions(), moved),
        [&](std::size_t i, ConfigurationComplex& built) {
            return detail::check(0, [&] {
                                     return built = detail::complete(detail::periodic_levels_parts(
                                                torus_levels(configurations[i]), 2, rule, caches.local()));
                                 },
                                 [](const LatticePoint&) { return true; },
                                 [](const CellComplex&, std::span<const VertexHandle>) { return false; });
        },
        [&](std::size_t i) { return detail::periodic_levels_parts(torus_levels(configurations[i]), 2, rule, caches.local()); },
        [&](const detail::FormArrays& k, const TorusMotion& m) { return detail::torus_form(k, m, octant); });
    const std::vector<ConfigurationReport> windows = detail::check_by_congruence(
        detail::congruence(configurations, detail::all_symmetries(), moved),
        [&](std::size_t i, ConfigurationComplex& built) {
            return detail::check_window(0, octant, [&] {
                return built = detail::complete(detail::window_levels_parts(as_levels(configurations[i]), rule, caches.local()));
            });
        },
        [&](std::size_t i) { return detail::window_levels_parts(as_levels(configurations[i]), rule, caches.local()); },
        detail::symmetric_form);

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
