#pragma once
// A configuration on the 3-torus (DESIGN.md section 4, "embed periodically").
//
// The torus is 4x4x4 coarse leaves = 2x2x2 octant cubes; bit b of the mask is the octant
// cube with min corner (2*(b&1), 2*((b>>1)&1), 2*((b>>2)&1)) (coarse units), set = fine.
// Fine octant cubes become 4x4x4 hexes of U/2; coarse ones 2x2x2 leaves, each replaced by
// the rule's placement (or a plain hex). Lattice keys are taken modulo the period 4U, so
// the complex is closed and every vertex is interior. Leaf contexts wrap around (octant
// cube indices mod 2). Every 2x2x2 window of the torus is again one of the 256 masks
// (all in the mask's class: the 8 application points see its reflections).
#include <array>
#include <functional>

#include "dualhex/checkers/configuration_report.hpp"
#include "dualhex/schemes/element_library.hpp"

namespace dualhex {

/// Throws what the rule throws (e.g. UnknownPatternError), std::out_of_range for an
/// element the library lacks, std::invalid_argument for a placement leaving its leaf.
[[nodiscard]] ConfigurationComplex build_periodic_configuration(std::uint8_t mask, const TransitionRule& rule,
                                                                const ElementLibrary& library);

/// Builds and checks (validate with every interior check, dual cubes, histograms). Never
/// throws for rule/library problems: they come back as built = false with the message.
[[nodiscard]] ConfigurationReport check_periodic_configuration(std::uint8_t mask, const TransitionRule& rule,
                                                               const ElementLibrary& library);

/// A periodic grid of n_octants^3 octant cubes, each at level(ox, oy, oz) in {0, 1, 2}
/// (0 coarsest: 2x2x2 leaves; 1: 4x4x4; 2: 8x8x8, plain hexes). Leaves of levels 0 and 1
/// get the rule's placement with contexts that include LeafContext::edge_two_finer, so a weak
/// rule sees the two-level jumps. The caller keeps face-adjacent octant cubes within one
/// level of each other (weak balance). Lattice: a level-1 leaf is U, level 0 is 2U.
[[nodiscard]] ConfigurationComplex build_periodic_levels(const std::function<int(int, int, int)>& level, int n_octants,
                                                         const TransitionRule& rule, const ElementLibrary& library);
[[nodiscard]] ConfigurationReport check_periodic_levels(const std::function<int(int, int, int)>& level, int n_octants,
                                                        const TransitionRule& rule, const ElementLibrary& library);

/// The same configuration in its window: the 8 octant cubes around the application point
/// (the origin), levels[b] for octant b (grid convention), the octants beyond extended
/// outward; only vertices strictly inside the window are checked.
[[nodiscard]] ConfigurationComplex build_window_levels(const std::array<int, 8>& levels, const TransitionRule& rule,
                                                       const ElementLibrary& library);
[[nodiscard]] ConfigurationReport check_window_levels(const std::array<int, 8>& levels, const TransitionRule& rule,
                                                      const ElementLibrary& library);

}  // namespace dualhex
