#pragma once
// What each vertex of a hex mesh is tied to, handed from the stages that place boundary
// vertices (pad, features) to the stages that move vertices (smooth, optimise): an
// interior vertex moves freely, a surface vertex stays on the input surface, a curve
// vertex on one feature curve of the input, a corner vertex does not move.
#include <cstdint>
#include <vector>

namespace dualhex::mesher {

enum class VertexRole : std::uint8_t { Interior, Surface, Curve, Corner };

struct VertexConstraints {
    std::vector<VertexRole> role;    ///< (points)
    std::vector<std::int32_t> curve; ///< (points): feature curve index for Curve, else -1

    /// All `n` vertices interior.
    [[nodiscard]] static VertexConstraints interior(std::size_t n) {
        return {std::vector<VertexRole>(n, VertexRole::Interior), std::vector<std::int32_t>(n, -1)};
    }
};

}  // namespace dualhex::mesher
