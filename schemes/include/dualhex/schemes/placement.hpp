#pragma once
// Placing atomic elements: the pluggable transition rule.
//
// Units: coarse-leaf units (one leaf of the level being decided = 1). An application point
// P is an octant corner (even coordinates). A leaf has exactly one corner that is an
// application point; it lies at P + [0,d_x] x [0,d_y] x [0,d_z], d in {+1,-1}^3 (the leaf
// direction). The leaf's LOCAL frame is the world reflected by diag(d) about P: in it the
// leaf is [0,1]^3 and its own octant cube (its parent) is [0,2]^3.
//
// A LeafContext is what a rule may look at: P, d, and the 4x4x4 octant-cube neighbourhood
// of P in the local frame. fine(i,j,k), i,j,k in {-2,-1,0,1}, is the octant-sized cube with
// min corner (2i,2j,2k) in the local frame (so (0,0,0) is the leaf's own octant, which is
// always coarse, and {-1,0}^3 are the 8 octants around P).
//
// A Placement{element, s} maps canonical point p (the element's leaf [0,U]^3, application
// point at the origin) to world point P*U + diag(d)(s(p)): world_symmetry() is that one
// CubeSymmetry. Reflections (determinant -1) are handled by topology's transform / the
// library's instance, which flip the cells' half-faces.
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "dualhex/topology/cube_symmetry.hpp"
#include "dualhex/topology/lattice.hpp"

namespace dualhex {

struct Placement {
    std::string element;    ///< element name in the ElementLibrary
    CubeSymmetry symmetry;  ///< acts in the leaf's local frame, about the application point
    bool operator==(const Placement&) const = default;
};

struct LeafContext {
    LatticePoint application_point;     ///< P, in coarse-leaf units of the leaf's level
    std::array<int, 3> direction{1, 1, 1};  ///< d: the leaf is P + [0,d]
    /// Bit neighbourhood_bit(i,j,k) set iff that local octant cube is fine.
    std::uint64_t neighbourhood = 0;
    /// Weakly balanced grids: bit a set iff the leaf-sized cell sharing the leaf's inner
    /// a-edge (its diagonal neighbour across that edge, inside the octant at local
    /// -e_b - e_c) holds leaves two or more levels finer than the leaf. Zero in strongly
    /// balanced grids.
    std::uint8_t edge_two_finer = 0;

    [[nodiscard]] static constexpr int neighbourhood_bit(int i, int j, int k) {
        return (i + 2) + 4 * (j + 2) + 16 * (k + 2);
    }
    /// i,j,k in {-2,-1,0,1} (local frame); throws std::out_of_range otherwise.
    [[nodiscard]] bool fine(int i, int j, int k) const;
    void set_fine(int i, int j, int k, bool value = true);
    /// Bit `axis` of edge_two_finer (axis 0, 1, 2).
    [[nodiscard]] bool two_finer_across_edge(int axis) const { return (edge_two_finer >> axis) & 1U; }
    void set_two_finer_across_edge(int axis, bool value = true) {
        const auto bit = static_cast<std::uint8_t>(1U << axis);
        edge_two_finer = static_cast<std::uint8_t>(value ? (edge_two_finer | bit) : (edge_two_finer & ~bit));
    }

    /// The 8 octants around P as a grid-convention configuration mask in the LOCAL frame:
    /// bit b = octant (b&1 ? +x : -x, b&2 ? +y : -y, b&4 ? +z : -z) is fine.
    [[nodiscard]] std::uint8_t local_configuration() const;
    /// The 7 octants around P other than the leaf's own, named by their negative local
    /// axes as in the derivation notes: e.g. "{Y,XY,YZ,XYZ}" ("{}" if none is fine).
    [[nodiscard]] std::string local_pattern_name() const;
    /// diag(d).
    [[nodiscard]] CubeSymmetry frame() const;
    /// "P=(..) d=(..) pattern {..} neighbourhood 0x..".
    [[nodiscard]] std::string describe() const;
};

/// A world-frame 64-bit neighbourhood (bit neighbourhood_bit(w) = octant cube with min
/// corner P + 2w in WORLD coordinates) seen in the local frame of a leaf with direction d:
/// per axis with d = -1, index i <-> -1 - i.
[[nodiscard]] std::uint64_t to_local_neighbourhood(std::uint64_t world, const std::array<int, 3>& direction);

/// The symmetry that maps canonical element points into the world (about P):
/// diag(d) composed with the placement's symmetry.
[[nodiscard]] CubeSymmetry world_symmetry(const LeafContext& context, const Placement& placement);

/// Thrown by a rule that has no element for a leaf's pattern.
class UnknownPatternError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class TransitionRule {
public:
    virtual ~TransitionRule();
    /// The element for this leaf, or std::nullopt for a plain hexahedron. May throw
    /// (UnknownPatternError for a pattern the rule does not cover).
    [[nodiscard]] virtual std::optional<Placement> place(const LeafContext& context) const = 0;
    [[nodiscard]] virtual std::string name() const { return "rule"; }
    /// The local octant cubes (LeafContext::neighbourhood bits) place() may depend on: a
    /// rule whose reach is smaller than all 64 must ignore the other bits (the strong rule
    /// masks its input, so this holds by construction). The compositional argument
    /// (checkers/compositional.hpp) enumerates exactly these bits.
    [[nodiscard]] virtual std::uint64_t reach() const { return ~std::uint64_t{0}; }
};

/// Test rule: the flat transition only. Among the 7 octants around P other than the leaf's
/// own: exactly the 4 with local y < 0 fine -> F (identity); none fine -> hexahedron;
/// anything else -> UnknownPatternError("no element for local pattern ...").
class FlatOnlyRule : public TransitionRule {
public:
    [[nodiscard]] std::optional<Placement> place(const LeafContext& context) const override;
    [[nodiscard]] std::string name() const override { return "flat-only"; }
};

}  // namespace dualhex
