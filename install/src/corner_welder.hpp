#pragma once
// Internal: welding of the points on finest-level grid corners through a dense array.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "dualhex/topology/complex_builder.hpp"

namespace dualhex::detail {

// Welds the points on finest-level grid corners (multiples of the unit U inside the root)
// through a dense array indexed by corner, every other point through the builder's hash
// table. The two sets are disjoint, so every point still gets exactly one vertex, numbered
// in first-use order as before; but corners, most of the points, are found where the leaf
// order puts them (the array is in the leaves' lexicographic order) instead of at random
// slots of a large table. Off for grids whose corner array would dwarf the grid (deep,
// sparse ones): then everything is hashed. A welding chunk (chunked_weld.hpp) gets one over
// its leaves' box: the same first-use numbering, without hashing most of its points.
class CornerWelder {
public:
    /// Dense over every corner of the root (levels up to max_level).
    CornerWelder(ComplexBuilder& builder, std::int64_t unit, int max_level, std::size_t n_leaves)
        : CornerWelder(builder, unit, {0, 0, 0}, max_level > 20 ? std::array<std::int64_t, 3>{-1, -1, -1} : root_extent(max_level),
                       n_leaves) {}
    /// Dense over the corners of the box [lo, hi] (finest-level corner indices, inclusive):
    /// those of a range of leaves (a welding chunk), whose other points are rare.
    CornerWelder(ComplexBuilder& builder, std::int64_t unit, std::array<std::int64_t, 3> lo, std::array<std::int64_t, 3> hi,
                 std::size_t n_leaves)
        : builder_(&builder), unit_(unit), lo_(lo) {
        std::uint64_t corners = 1;
        for (int a = 0; a < 3; ++a) {
            if (hi[a] < lo[a]) return;
            n_[a] = hi[a] - lo[a] + 1;
            corners *= static_cast<std::uint64_t>(n_[a]);
            if (corners > (std::uint64_t{1} << 40)) return;
        }
        if (corners > std::max<std::uint64_t>(std::uint64_t{1} << 22, 16 * static_cast<std::uint64_t>(n_leaves))) return;
        // calloc: untouched parts of the array cost no memory (fresh zero pages).
        ids_.reset(static_cast<std::uint32_t*>(std::calloc(corners, sizeof(std::uint32_t))));
    }

    [[nodiscard]] bool dense() const { return ids_ != nullptr; }

    /// The vertex at finest-level corner (x, y, z), i.e. at the point U * (x, y, z).
    VertexHandle corner(std::int64_t x, std::int64_t y, std::int64_t z) {
        const LatticePoint p{x * unit_, y * unit_, z * unit_};
        x -= lo_[0], y -= lo_[1], z -= lo_[2];
        if (!ids_ || x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) return builder_->add_vertex(p);
        std::uint32_t& id = ids_.get()[static_cast<std::size_t>((x * n_[1] + y) * n_[2] + z)];
        if (id == 0) id = static_cast<std::uint32_t>(builder_->add_vertex_unwelded(p).idx) + 1;
        return VertexHandle(static_cast<std::int32_t>(id - 1));
    }

    VertexHandle operator()(const LatticePoint& p) {
        if (ids_ && p.x % unit_ == 0 && p.y % unit_ == 0 && p.z % unit_ == 0)
            return corner(p.x / unit_, p.y / unit_, p.z / unit_);
        return builder_->add_vertex(p);
    }

private:
    struct Free {
        void operator()(std::uint32_t* p) const { std::free(p); }
    };
    static std::array<std::int64_t, 3> root_extent(int max_level) {
        const std::int64_t n = std::int64_t{1} << max_level;
        return {n, n, n};
    }

    ComplexBuilder* builder_;
    std::int64_t unit_;
    std::array<std::int64_t, 3> lo_{}, n_{};
    std::unique_ptr<std::uint32_t, Free> ids_;
};

}  // namespace dualhex::detail
