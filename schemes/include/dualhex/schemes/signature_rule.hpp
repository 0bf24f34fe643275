#pragma once
// The transition rule for strongly balanced paired grids (docs/scheme-derivation.md).
//
// A coarse leaf's element is fixed by its *signature*, read off the octants around its
// coarse octant Q (LeafContext, local frame, Q = [0,2]^3, application point at the origin):
//
//   interfaces  the inner faces whose octant across is fine (local octant -e_a);
//   tets        inner edges (along axis a) whose two adjacent faces are not interfaces but
//               whose diagonal octant is fine: a bend tetrahedron at the edge's far end;
//   lower[n]    for every interface face with normal n: the axis along which the chain that
//               passes BELOW at the crossing runs. A chain is bent if Q has an interface
//               normal to its running direction (on either side of Q, octants -e and +e);
//               a bent chain passes below an unbent one; otherwise the chain running along
//               (n + 1) mod 3 does (a cyclic convention in world axes: reflections keep the
//               axis labels, so every leaf evaluates it the same way).
//
// The element is the one of F, F+C, C1, C2, C3, E, VS, VC whose canonical signature, under
// one of the 6 axis permutations, equals the required one.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/schemes/placement.hpp"

namespace dualhex {

struct Signature {
    unsigned interfaces = 0;  ///< bit a: inner face normal to axis a is an interface
    unsigned tets = 0;        ///< bit a: bend tetrahedron at the far end of the a-edge
    int lower[3] = {-1, -1, -1};  ///< per interface normal n: axis of the lower chain, else -1

    bool operator==(const Signature&) const = default;
    [[nodiscard]] bool empty() const { return interfaces == 0 && tets == 0; }
    /// The signature after relabelling canonical axis i as axis s[i].
    [[nodiscard]] Signature permuted(const std::array<int, 3>& s) const;
    [[nodiscard]] std::string to_string() const;
};

/// The signature a leaf needs, from its context.
[[nodiscard]] Signature required_signature(const LeafContext& context);

/// One of the 8 strongly balanced elements with its canonical signature.
struct CanonicalElement {
    std::string name;
    Signature signature;
};
[[nodiscard]] const std::vector<CanonicalElement>& strong_elements();

/// The 6 axis permutations, identity first (s[i] = the local axis canonical axis i goes to).
[[nodiscard]] const std::array<std::array<int, 3>, 6>& axis_permutations();
/// The placement putting canonical axis i onto local axis s[i] (its symmetry is s^-1).
[[nodiscard]] Placement permutation_placement(const std::string& element, const std::array<int, 3>& s);

/// The local octant cubes the strong rule reads: the leaf's own octant (0,0,0), the three
/// across its inner faces (-e_a), the three diagonal to its inner edges (-e_b - e_c) and the
/// three across its far faces (+e_a). Not the corner-diagonal (-1,-1,-1).
[[nodiscard]] std::uint64_t strong_reach();

class StrongRule : public TransitionRule {
public:
    /// Depends on context.neighbourhood & strong_reach() only (the rest is masked off before
    /// anything is read; edge_two_finer is ignored).
    [[nodiscard]] std::optional<Placement> place(const LeafContext& context) const override;
    [[nodiscard]] std::string name() const override { return "strong"; }
    [[nodiscard]] std::uint64_t reach() const override { return strong_reach(); }
};

}  // namespace dualhex
