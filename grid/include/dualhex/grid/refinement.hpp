#pragma once
// Least refinements: balancing and pairing only ever split leaves, and only the splits
// that are forced, so the result is the unique coarsest grid refining the input that
// satisfies the condition. Inputs and outputs are LeafGrids (valid tilings); output
// leaves are sorted by (level, i, j, k) and carry no source lines.
//
// Scales to 10^7 leaves: nodes live in a flat hash map of packed 128-bit keys.
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"

namespace dualhex {

/// The least refinement that is strongly (or weakly) balanced. Level-by-level ripple:
/// interior nodes, finest level first, force their same-level neighbours (26 for Strong,
/// 6 face neighbours for Weak) to exist by splitting the leaf covering them; the split
/// nodes are queued at their (coarser) level.
[[nodiscard]] LeafGrid balance(const LeafGrid& grid, Balance mode);

/// The least refinement that is paired (every leaf's 7 siblings are leaves): a node with
/// both leaf and subdivided children has its leaf children split. Ignores balance.
[[nodiscard]] LeafGrid pair_only(const LeafGrid& grid);

/// The least refinement that is both paired and balanced (`mode`): pairing and balancing
/// alternate until neither splits anything. This is what the schemes need.
[[nodiscard]] LeafGrid pair(const LeafGrid& grid, Balance mode);

}  // namespace dualhex
