#pragma once
// The transition rule for weakly balanced paired grids (docs/scheme-derivation.md, "Weakly
// balanced grids"): the strong rule, plus the MR elements. Under weak balance the only new
// situation for a coarse leaf is a concave inner edge (both adjacent faces interfaces)
// whose diagonal neighbour across that edge (the leaf-sized cell sharing it) holds leaves
// two levels finer (LeafContext::edge_two_finer): the finer
// transition's chains bend around that edge through this leaf. The element is then the
// strong element (E, VS or VC) truncated at the midpoint of each such edge: E-MR, VS-MR,
// VC1-MR, VC2-MR, VC3-MR (schemes/elements). Their canonical frames: E-MR and VS-MR are
// truncated on the x-edge; VCk-MR on the first k of the x-, y-, z-edges.
#include "dualhex/schemes/signature_rule.hpp"

namespace dualhex {

/// Bit a set iff the leaf's inner a-edge is concave and its diagonal octant is two levels finer.
[[nodiscard]] unsigned mr_edges(const LeafContext& context);

/// What the weak rule may see of a context: the neighbourhood masked to strong_reach()
/// (the MR test reads only the two inner-face octants of an edge, which are in it) and
/// edge_two_finer masked to the concave inner edges (both adjacent inner-face octants
/// fine): the only edges whose bit the MR test can use.
[[nodiscard]] LeafContext weak_visible(const LeafContext& context);

class WeakRule : public TransitionRule {
public:
    /// Depends on weak_visible(context) only: it is computed first and nothing else is read.
    [[nodiscard]] std::optional<Placement> place(const LeafContext& context) const override;
    [[nodiscard]] std::string name() const override { return "weak"; }
    /// The octant cubes read; beyond them, edge_two_finer at concave inner edges (weak_visible).
    [[nodiscard]] std::uint64_t reach() const override { return strong_reach(); }
};

}  // namespace dualhex
