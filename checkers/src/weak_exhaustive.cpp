#include "dualhex/checkers/weak_exhaustive.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include <tbb/parallel_for.h>

#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/checkers/torus_classes.hpp"
#include "dualhex/grid/configurations.hpp"
#include "dualhex/install/element_templates.hpp"
#include "oriented_form.hpp"
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

// The class path of run_weak_exhaustive: each torus (window) class's representative gets
// the full check; every other member is built and proved to be the exact image of its
// representative's complex under a motion of the torus (a symmetry about the application
// point), oriented_form.hpp; the check is invariant under those motions, so the member's
// outcome is its representative's. What depends on the placements themselves (elements
// used) is read from the member's own build. A member that is not such an image, or whose
// representative fails, is checked itself: the coverage is that of checking every one.

// What the tally needs of one check.
struct Outcome {
    bool ok = false;
    std::string summary;
    std::map<std::string, std::size_t> elements;
    int max_valence = 0;
};

Outcome outcome_of(const ConfigurationReport& r) {
    return {r.ok(), r.summary(), r.elements, r.dual_edge_valences.empty() ? 0 : r.dual_edge_valences.rbegin()->first};
}

std::map<std::string, std::size_t> elements_of(const ConfigurationComplex& built) {
    std::map<std::string, std::size_t> out;
    for (const PlacedLeaf& leaf : built.coarse_leaves) ++out[leaf.placement ? leaf.placement->element : "hex"];
    if (built.fine_hexes) out["fine"] = built.fine_hexes;
    return out;
}

// The assignment moved by a window symmetry (octant b is on the + side of axis a iff bit a).
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

// Per configuration: its class's representative (the first of its orbit) and a motion
// taking the representative's assignment to it.
template <class Motion>
struct Congruence {
    std::vector<std::size_t> representative;
    std::vector<Motion> motion;
};

template <class Motion>
Congruence<Motion> congruence(const std::vector<LevelAssignment>& all, const std::vector<Motion>& motions) {
    Congruence<Motion> out;
    std::map<LevelAssignment, std::size_t> first;
    for (std::size_t i = 0; i < all.size(); ++i) {
        LevelAssignment key = all[i];
        for (const Motion& m : motions) key = std::min(key, moved_by(all[i], m));
        const std::size_t rep = first.emplace(key, i).first->second;
        out.representative.push_back(rep);
        out.motion.push_back(*std::find_if(motions.begin(), motions.end(), [&](const Motion& m) { return moved_by(all[rep], m) == all[i]; }));
    }
    return out;
}

TorusMotion inverse_of(const TorusMotion& m) { return m.inverse(); }
CubeSymmetry inverse_of(const CubeSymmetry& s) { return s.inverse(); }

// Every configuration's outcome in one domain: `check(i, built)` checks configuration i
// (keeping its complex in `built`), `build(i)` only builds it, `form(complex, motion)` is the
// moved oriented form. A member is moved back onto its representative and compared.
template <class Motion, class Check, class Build, class Form>
std::vector<Outcome> by_class(const Congruence<Motion>& classes, Check&& check, Build&& build, Form&& form) {
    const std::size_t n = classes.representative.size();
    std::vector<Outcome> out(n);
    std::vector<detail::OrientedForm> forms(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        if (classes.representative[i] != i) return;
        ConfigurationComplex built;
        out[i] = outcome_of(check(i, built));
        if (out[i].ok) forms[i] = form(built.complex, Motion{});
    });
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        const std::size_t rep = classes.representative[i];
        if (rep == i) return;
        if (out[rep].ok && !forms[rep].empty()) {
            try {
                const ConfigurationComplex built = build(i);
                if (form(built.complex, inverse_of(classes.motion[i])) == forms[rep]) {
                    out[i] = out[rep];
                    out[i].elements = elements_of(built);
                    return;
                }
            } catch (const std::exception&) {  // the full check below reports it
            }
        }
        ConfigurationComplex built;
        out[i] = outcome_of(check(i, built));
    });
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
    // Tori: classes under the 384 motions of the torus; windows: under the 48 symmetries.
    const std::vector<Outcome> tori = by_class(
        congruence(configurations, torus_motions()),
        [&](std::size_t i, ConfigurationComplex& built) {
            return detail::check(0, [&] { return built = build_periodic_levels(torus_levels(configurations[i]), 2, rule, library); },
                                 [](const LatticePoint&) { return true; },
                                 [](const CellComplex&, std::span<const VertexHandle>) { return false; });
        },
        [&](std::size_t i) { return build_periodic_levels(torus_levels(configurations[i]), 2, rule, library); },
        [&](const CellComplex& k, const TorusMotion& m) {
            return detail::oriented_form(k, [&](const LatticePoint& p) { return m.apply(p, octant); }, m.symmetry.determinant() < 0);
        });
    std::vector<CubeSymmetry> symmetries;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) symmetries.push_back(CubeSymmetry::from_index(i));
    const std::vector<Outcome> windows = by_class(
        congruence(configurations, symmetries),
        [&](std::size_t i, ConfigurationComplex& built) {
            return detail::check_window(0, octant, [&] { return built = build_window_levels(as_levels(configurations[i]), rule, library); });
        },
        [&](std::size_t i) { return build_window_levels(as_levels(configurations[i]), rule, library); },
        [&](const CellComplex& k, const CubeSymmetry& s) {
            return detail::oriented_form(k, [&](const LatticePoint& p) { return s.apply(p); }, !s.is_rotation());
        });

    std::set<LevelAssignment> classes, three;
    for (std::size_t n = 0; n < configurations.size(); ++n) {
        const LevelAssignment& lv = configurations[n];
        ++r.configurations;
        const LevelAssignment key = canonical(lv);
        classes.insert(key);
        if (*std::max_element(lv.begin(), lv.end()) == 2) three.insert(key);
        const Outcome& report = tori[n];
        const Outcome& window = windows[n];
        r.periodic_passed += report.ok;
        r.window_passed += window.ok;
        if (report.ok && window.ok)
            ++r.passed;
        else
            r.failures.push_back((report.ok ? "window " + window.summary : "torus " + report.summary));
        for (const auto& [name, count] : report.elements) r.elements[name] += count;
        r.max_dual_edge_valence = std::max(r.max_dual_edge_valence, report.max_valence);
    }
    r.classes = static_cast<int>(classes.size());
    r.three_level_classes = static_cast<int>(three.size());
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

}  // namespace dualhex
