#pragma once
// The weakly balanced configuration space and its exhaustive check.
//
// A weak configuration gives each of the 8 octants around an application point a level
// l, l+1 or l+2 (relative to the coarsest present); weak balance: octants sharing a face
// differ by at most one level. Enumerated: 487 such assignments, 255 with two levels and
// 232 with three; classes under the 48 cube symmetries (acting on the octants). Each is
// checked in both domains: the periodic embedding (build_periodic_levels with n = 2),
// where every vertex is interior, and the window around the application point
// (build_window_levels, octants extended outward, inner vertices checked).
#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "dualhex/checkers/configuration_report.hpp"

namespace dualhex {

class ElementLibrary;

/// levels[b] for octant b (grid convention: bit 0 = +x side, ...).
using LevelAssignment = std::array<std::uint8_t, 8>;

/// All weakly balanced assignments with minimum level 0 (487), in a fixed order.
[[nodiscard]] std::vector<LevelAssignment> weak_configurations();
/// The assignment as build_periodic_levels' level function on the torus of 2x2x2 octant
/// cubes (n_octants = 2): cube (x, y, z) is octant x | y << 1 | z << 2.
[[nodiscard]] std::function<int(int, int, int)> torus_levels(const LevelAssignment& levels);
/// The assignment's canonical form: the smallest image under the 48 symmetries.
[[nodiscard]] LevelAssignment canonical(const LevelAssignment& levels);

struct WeakExhaustiveResult {
    int configurations = 0, passed = 0;    ///< passed: both domains
    int periodic_passed = 0, window_passed = 0;
    int classes = 0, three_level_classes = 0;
    int max_dual_edge_valence = 0;
    std::map<std::string, std::size_t> elements;  ///< placements over all configurations
    std::vector<std::string> failures;            ///< summaries of failing configurations
    double seconds = 0;
    [[nodiscard]] bool all_passed() const { return passed == configurations; }
};

[[nodiscard]] WeakExhaustiveResult run_weak_exhaustive(const TransitionRule& rule, const ElementLibrary& library);

}  // namespace dualhex
