#pragma once
// The weak rule's reduction facts (proofs/README.md, "Weak balance: what is proved"),
// computed: what the rule reads, the weak lemma (no fine octant cube at the application
// point: a plain cube, whatever else is fine or two levels finer), and the rule's whole
// visible domain (every context it can tell apart, once each).
//
// Units and frames as in compositional.hpp. A weak context is the strong reach's 10 octant
// bits (own octant coarse) plus LeafContext::edge_two_finer, which the rule reads only at a
// concave inner edge (weak_visible, schemes/weak_rule.hpp).
#include <cstddef>
#include <map>
#include <string>

#include <filesystem>

#include "dualhex/checkers/certificate.hpp"
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/schemes/placement.hpp"

namespace dualhex {

class ElementLibrary;

struct WeakLemmaResult {
    std::string rule;
    int reach_octants = 0;  ///< octant cubes the rule reads (TransitionRule::reach())
    /// The weak lemma: contexts with none of the 7 octant cubes at P fine (every value of
    /// the other reach bits and of the 3 edge bits), and those the rule leaves plain.
    int lemma_contexts = 0, lemma_plain = 0;
    /// Every context of the visible domain (own octant coarse: 2^9 octant values x 2^3 edge
    /// values): placed, plain, refused (the rule throws).
    int visible_contexts = 0, placed = 0, plain = 0, refused = 0;
    /// Contexts whose edge bits at non-concave edges are set, and those whose outcome equals
    /// the outcome with those bits cleared (the rule ignores them).
    int nonconcave_contexts = 0, nonconcave_ignored = 0;
    /// Contexts with a concave edge whose bit changes the outcome (the MR elements).
    int mr_contexts = 0;
    std::map<std::string, int> elements;  ///< placed contexts per element
    [[nodiscard]] bool lemma_holds() const { return lemma_contexts > 0 && lemma_plain == lemma_contexts; }
    [[nodiscard]] bool all_passed() const {
        return lemma_holds() && nonconcave_ignored == nonconcave_contexts && refused == 0;
    }
};

/// Computes the facts above for a rule (the weak rule: all pass).
[[nodiscard]] WeakLemmaResult check_weak_lemmas(const TransitionRule& rule);

/// The grid of "the level spread at a point": a weakly balanced paired grid (root level 0,
/// coarse level `m` >= 2) in which the root's centre P (2^(m-1) in level-m units) lies in
/// leaves of the four levels m..m+3, the largest spread weak balance allows at a point
/// (proofs/README.md, W3): the least paired weakly balanced refinement of the uniform
/// level-m grid with the cells at P on the side `corner` (bit a set: x_a >= P_a) split down
/// to level m+3. Its 8 octant cubes at P have the levels of the only four-level octant
/// assignments (one per corner).
[[nodiscard]] LeafGrid spread_three_grid(int m, int corner = 7);

/// The 8 grids spread_three_grid(2, corner), installed with the weak rule (outside root
/// coarse) and checked, as 8 `installation` certificates over the root box in
/// dir/spread-0-7.cert (covers: the corner), manifest `covers 8`; throws if one fails.
/// What `dualhex certify` writes into proofs/certificates/weak_spread/.
CertificateSet certify_spread_grids(const ElementLibrary& library, const std::filesystem::path& dir);

/// What a window B(g) (2x2x2 level-m cells around g, proofs/README.md "Compositional
/// argument", step 5) reads once its level-m cells may hold level-(m+1) leaves with elements
/// (the weak case): the size of the joint enumeration a box window would need.
struct WeakWindowReads {
    std::array<int, 3> parity{};
    int octants = 0;       ///< level-(m-1) octant cubes read by the 8 level-m leaves (R(t))
    /// Level-m cells whose status some leaf of the window reads: each of the 8 cells (is it
    /// a leaf, 8 level-(m+1) leaves or finer) by its own leaves; each level-m leaf's 3 edge
    /// cells; each of the 64 level-(m+1) leaves' 10 reach cells.
    int cells = 0;
    int shared_cells = 0;  ///< of those, read by two or more of the 72 possible leaves
    /// Application points of the 64 level-(m+1) leaves (the 27 lattice points of B(g)).
    int application_points = 0;
};
[[nodiscard]] std::vector<WeakWindowReads> weak_window_reads();

/// The levels of the leaves of `grid` containing the point p (given in level-`level` units).
[[nodiscard]] std::vector<int> levels_at(const LeafGrid& grid, const std::array<std::int64_t, 3>& p, int level);

}  // namespace dualhex
