#pragma once
// The 48 symmetries of the cube (the hyperoctahedral group B3) as signed permutations of
// the axes: image[i] = sign[i] * p[perm[i]]. 24 of them are rotations (det +1), 24 are
// rotations composed with a reflection (det -1).
//
// They act on integer lattice points about the origin; `apply_about` acts about the
// centre of a box [0, extent]^3, which is how a symmetry moves a leaf or a scheme inside
// its cube while keeping every coordinate an integer.
#include <array>
#include <cstdint>
#include <string>

#include "dualhex/topology/lattice.hpp"

namespace dualhex {

class CubeSymmetry {
public:
    static constexpr int kOrder = 48;

    constexpr CubeSymmetry() = default;  // identity
    constexpr CubeSymmetry(std::array<int, 3> perm, std::array<int, 3> sign) : perm_(perm), sign_(sign) {}

    /// The i-th element, 0 <= i < 48; index 0 is the identity. Stable order:
    /// i = 8 * permutation_rank + sign_bits (bit a set = axis a negated).
    static CubeSymmetry from_index(int i);
    [[nodiscard]] int index() const;

    [[nodiscard]] int perm(int axis) const { return perm_[axis]; }
    [[nodiscard]] int sign(int axis) const { return sign_[axis]; }
    [[nodiscard]] int determinant() const;
    [[nodiscard]] bool is_rotation() const { return determinant() == 1; }

    /// (this * other)(p) = this(other(p)).
    [[nodiscard]] CubeSymmetry compose(const CubeSymmetry& other) const;
    [[nodiscard]] CubeSymmetry inverse() const;

    /// Acts about the origin. Inline: the checkers move every vertex of tens of thousands of
    /// complexes by it (their oriented forms), where the call cost as much as the work.
    [[nodiscard]] LatticePoint apply(const LatticePoint& p) const {
        LatticePoint q;
        for (int i = 0; i < 3; ++i) q[i] = sign_[static_cast<std::size_t>(i)] * p[perm_[static_cast<std::size_t>(i)]];
        return q;
    }
    /// Acts about the centre of the box [0, extent]^3 (maps the box onto itself).
    [[nodiscard]] LatticePoint apply_about(const LatticePoint& p, std::int64_t extent) const;
    /// Image of axis direction `axis` (0,1,2): returns the axis it maps to.
    [[nodiscard]] int image_axis(int axis) const;

    /// Human-readable form such as "(x,y,z)->(-y,x,z)".
    [[nodiscard]] std::string to_string() const;

    bool operator==(const CubeSymmetry&) const = default;

private:
    std::array<int, 3> perm_{0, 1, 2};
    std::array<int, 3> sign_{1, 1, 1};
};

}  // namespace dualhex
