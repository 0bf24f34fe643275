#pragma once
// The star run's assumptions about real grids (proofs/README.md W9 (ii), (iv), (v)) tested
// on one: at points v of a weakly balanced paired grid (every element position of a leaf),
// the configuration of the leaves at v is one the run enumerates, every status the run
// takes as forced has that value in the grid, and every implication it imposes (and each
// chain of them) holds there. Cells outside the root are skipped (the run is about grids on
// all of Z^3).
#include <cstddef>
#include <string>
#include <vector>

#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/grid/leaf_grid.hpp"

namespace dualhex {

/// A deliberately wrong rule, to show the test catches it: "f(x) = 1 implies f of x's first
/// child", or "a leaf at v one level finer inside x forces f(x) = 1".
enum class WeakStarRuleMutation { None, ImpliesChildFine, OneLevelFinerForcesFine };

struct WeakStarAssumptionReport {
    long vertices = 0;        ///< points v checked (all their leaves inside the root)
    long statuses = 0;        ///< (v, leaf, read status) inside the root checked
    long forced = 0;          ///< of those, forced by the configuration
    long implications = 0;    ///< (fine status, status a chain of implications names) checked
    std::vector<std::string> violations;  ///< the first few
    long violated = 0;
    [[nodiscard]] bool ok() const { return statuses > 0 && violated == 0; }
};

/// Every `stride`-th leaf's element positions as the points v.
[[nodiscard]] WeakStarAssumptionReport check_weak_star_assumptions(
    const LeafGrid& grid, const WeakStarInfluence& influence, std::size_t stride = 1,
    WeakStarRuleMutation mutation = WeakStarRuleMutation::None);

}  // namespace dualhex
