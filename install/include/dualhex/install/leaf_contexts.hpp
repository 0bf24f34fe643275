#pragma once
// A leaf's context: its application point P and direction d (level-L units) and the 4x4x4
// octant cubes around P (level L-1), fine iff covered by leaves of level > L (pairing:
// iff their children are subdivided); cubes outside the root per OutsideRoot. The rule
// reads nothing else (schemes/placement.hpp).
#include <cstddef>
#include <vector>

#include "dualhex/install/install.hpp"

namespace dualhex {

/// The contexts of all leaves (fast: fine octant cubes are scattered to the application
/// points they can reach). Does not check pairing/balance. contexts[n] is leaf n's.
[[nodiscard]] std::vector<LeafContext> leaf_contexts(const LeafGrid& grid, OutsideRoot outside = OutsideRoot::Coarse);

/// One leaf's context by direct queries (reference implementation for tests).
[[nodiscard]] LeafContext leaf_context(const LeafGrid& grid, std::size_t leaf, OutsideRoot outside = OutsideRoot::Coarse);

}  // namespace dualhex
