#include "dualhex/topology/cube_symmetry.hpp"

#include <algorithm>
#include <stdexcept>

namespace dualhex {
namespace {

// The 6 permutations of (0,1,2) in lexicographic order.
constexpr std::array<std::array<int, 3>, 6> kPermutations{{
    {0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

}  // namespace

CubeSymmetry CubeSymmetry::from_index(int i) {
    if (i < 0 || i >= kOrder) throw std::out_of_range("cube symmetry index out of range: " + std::to_string(i));
    const auto& perm = kPermutations[static_cast<std::size_t>(i / 8)];
    const int bits = i % 8;
    return CubeSymmetry(perm, {bits & 1 ? -1 : 1, bits & 2 ? -1 : 1, bits & 4 ? -1 : 1});
}

int CubeSymmetry::index() const {
    const auto it = std::find(kPermutations.begin(), kPermutations.end(), perm_);
    const int rank = static_cast<int>(it - kPermutations.begin());
    const int bits = (sign_[0] < 0 ? 1 : 0) | (sign_[1] < 0 ? 2 : 0) | (sign_[2] < 0 ? 4 : 0);
    return 8 * rank + bits;
}

int CubeSymmetry::determinant() const {
    // sign of the permutation times the product of the signs
    int inversions = 0;
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            if (perm_[a] > perm_[b]) ++inversions;
    const int perm_sign = inversions % 2 == 0 ? 1 : -1;
    return perm_sign * sign_[0] * sign_[1] * sign_[2];
}

CubeSymmetry CubeSymmetry::compose(const CubeSymmetry& other) const {
    // this(other(p))[i] = sign[i] * other(p)[perm[i]] = sign[i] * other.sign[perm[i]] * p[other.perm[perm[i]]]
    std::array<int, 3> perm{}, sign{};
    for (int i = 0; i < 3; ++i) {
        perm[i] = other.perm_[perm_[i]];
        sign[i] = sign_[i] * other.sign_[perm_[i]];
    }
    return {perm, sign};
}

CubeSymmetry CubeSymmetry::inverse() const {
    // q = s(p): q[i] = sign[i] p[perm[i]]  =>  p[perm[i]] = sign[i] q[i]
    std::array<int, 3> perm{}, sign{};
    for (int i = 0; i < 3; ++i) {
        perm[perm_[i]] = i;
        sign[perm_[i]] = sign_[i];
    }
    return {perm, sign};
}

LatticePoint CubeSymmetry::apply_about(const LatticePoint& p, std::int64_t extent) const {
    LatticePoint q;
    for (int i = 0; i < 3; ++i) q[i] = sign_[i] > 0 ? p[perm_[i]] : extent - p[perm_[i]];
    return q;
}

int CubeSymmetry::image_axis(int axis) const {
    for (int i = 0; i < 3; ++i)
        if (perm_[i] == axis) return i;
    return -1;
}

std::string CubeSymmetry::to_string() const {
    static constexpr char kName[] = {'x', 'y', 'z'};
    std::string s = "(x,y,z)->(";
    for (int i = 0; i < 3; ++i) {
        if (i) s += ',';
        if (sign_[i] < 0) s += '-';
        s += kName[perm_[i]];
    }
    return s + ")";
}

}  // namespace dualhex
