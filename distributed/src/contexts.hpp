#pragma once
// The rule's context for leaves this rank installs (its own and its ghosts), from the
// points the context can ask about: the min corners of the 8 children of each of the 64
// octant cubes (level L-1) around the leaf's application point (install/leaf_contexts.hpp:
// "fine" reads those children, the weak rule's edge test a child's first child, which has
// the same min corner). Distinct cubes first, so shared neighbourhoods cost once.
#include <cstdint>
#include <vector>

#include "dualhex/install/install.hpp"
#include "level_oracle.hpp"

namespace dualhex::dist {

/// Morton indices of every point the contexts of `leaves` can query (unsorted, distinct).
[[nodiscard]] std::vector<std::uint64_t> context_points(const std::vector<Leaf>& leaves);

/// contexts[n] of leaves[n], each query answered by the oracle (install's leaf_context).
[[nodiscard]] std::vector<LeafContext> gather_contexts(const std::vector<Leaf>& leaves, const LevelOracle& oracle,
                                                       OutsideRoot outside);

}  // namespace dualhex::dist
