#pragma once
// Least refinements: balancing and pairing only ever split leaves, and only the splits
// that are forced, so the result is the unique coarsest grid refining the input that
// satisfies the condition. Inputs and outputs are LeafGrids (valid tilings); output
// leaves are sorted by (level, i, j, k) and carry no source lines.
//
// Computed as a closure, level by level from the finest (refinement.cpp): each level's
// interior nodes a sorted array of 128-bit keys, found and sorted in parallel (oneTBB), so
// the output is the same for any number of threads. Scales to 10^7 leaves.
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"

namespace dualhex {

/// The least refinement that is strongly (or weakly) balanced: interior nodes, finest
/// level first, force their same-level neighbours (26 for Strong, 6 face neighbours for
/// Weak) to be nodes, i.e. those neighbours' parents to be interior.
[[nodiscard]] LeafGrid balance(const LeafGrid& grid, Balance mode);

/// The least refinement that is paired (every leaf's 7 siblings are leaves): a node with
/// both leaf and subdivided children has its leaf children split. Ignores balance.
[[nodiscard]] LeafGrid pair_only(const LeafGrid& grid);

/// The least refinement that is both paired and balanced (`mode`): one sweep applying both
/// rules (pairing closes a level under siblings before it forces the level above). This is
/// what the schemes need.
[[nodiscard]] LeafGrid pair(const LeafGrid& grid, Balance mode);

}  // namespace dualhex
