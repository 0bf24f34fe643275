#pragma once
// A leaf's context: its application point P and direction d (level-L units) and the 4x4x4
// octant cubes around P (level L-1), fine iff covered by leaves of level > L (pairing:
// iff their children are subdivided); cubes outside the root per OutsideRoot. The rule
// reads nothing else (schemes/placement.hpp).
#include <cstddef>
#include <functional>
#include <vector>

#include "dualhex/install/install.hpp"

namespace dualhex {

/// The contexts of all leaves (fast: fine octant cubes are scattered to the application
/// points they can reach). Does not check pairing/balance. contexts[n] is leaf n's.
[[nodiscard]] std::vector<LeafContext> leaf_contexts(const LeafGrid& grid, OutsideRoot outside = OutsideRoot::Coarse);

/// One leaf's context by direct queries (reference implementation for tests).
[[nodiscard]] LeafContext leaf_context(const LeafGrid& grid, std::size_t leaf, OutsideRoot outside = OutsideRoot::Coarse);

/// "Is this cell (inside the root) a proper ancestor of some leaf?" The only question a
/// context asks of the grid; the cells asked about are level-L cells (and their first
/// children) inside the 4x4x4 octant cubes around the leaf's application point.
using SubdividedQuery = std::function<bool(const Leaf& cell)>;

/// The same context from the query alone, for a caller holding only part of the grid
/// (distributed/: the answers come from the ranks owning those cells).
[[nodiscard]] LeafContext leaf_context(const Leaf& leaf, const SubdividedQuery& is_subdivided,
                                       OutsideRoot outside = OutsideRoot::Coarse);

}  // namespace dualhex
