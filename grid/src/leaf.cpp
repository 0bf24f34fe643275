#include "dualhex/grid/leaf.hpp"

namespace dualhex {

bool Leaf::valid() const {
    if (level < 0 || level > kMaxLevel) return false;
    const std::int64_t n = extent();
    return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n;
}

Leaf parent(const Leaf& leaf) { return {leaf.level - 1, leaf.i >> 1, leaf.j >> 1, leaf.k >> 1}; }

Leaf ancestor(const Leaf& leaf, int level) {
    const int d = leaf.level - level;
    return {level, leaf.i >> d, leaf.j >> d, leaf.k >> d};
}

std::array<Leaf, 8> children(const Leaf& leaf) {
    std::array<Leaf, 8> out;
    for (int c = 0; c < 8; ++c)
        out[c] = {leaf.level + 1, 2 * leaf.i + (c & 1), 2 * leaf.j + (c >> 1 & 1), 2 * leaf.k + (c >> 2 & 1)};
    return out;
}

int child_index(const Leaf& leaf) {
    return static_cast<int>((leaf.i & 1) | (leaf.j & 1) << 1 | (leaf.k & 1) << 2);
}

LeafBox box_at(const Leaf& leaf, int level) {
    const int d = level - leaf.level;
    const LatticePoint lo{leaf.i << d, leaf.j << d, leaf.k << d};
    const std::int64_t side = std::int64_t{1} << d;
    return {lo, lo + LatticePoint{side, side, side}, level};
}

bool contains(const Leaf& outer, const Leaf& inner) {
    return outer.level <= inner.level && ancestor(inner, outer.level) == outer;
}

std::string to_string(const Leaf& leaf) {
    return std::to_string(leaf.level) + " " + std::to_string(leaf.i) + " " + std::to_string(leaf.j) + " " +
           std::to_string(leaf.k);
}

}  // namespace dualhex
