#pragma once
// The cells that touch a cell at the same level: 6 across faces, 12 across edges,
// 8 across vertices. Balance conditions are stated over these contacts.
#include <array>
#include <span>

#include "dualhex/grid/leaf.hpp"

namespace dualhex {

/// Strong balance constrains every contact (26 directions), weak balance faces only (6).
enum class Balance { Strong, Weak };

struct Offset {
    int dx, dy, dz;
    /// 1 = face, 2 = edge, 3 = vertex contact.
    [[nodiscard]] constexpr int order() const { return (dx != 0) + (dy != 0) + (dz != 0); }
};

/// The directions constrained by `mode`: 26 for Strong, the 6 face directions for Weak.
[[nodiscard]] std::span<const Offset> neighbour_offsets(Balance mode);

/// The same-level cell in direction `d` (may be outside the root: check valid()).
[[nodiscard]] inline Leaf neighbour(const Leaf& c, const Offset& d) {
    return {c.level, c.i + d.dx, c.j + d.dy, c.k + d.dz};
}

/// "face", "edge" or "vertex".
[[nodiscard]] const char* contact_name(const Offset& d);

}  // namespace dualhex
