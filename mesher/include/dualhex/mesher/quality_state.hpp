#pragma once
// The per-hex quality the geometric stages carry from one to the next, so each stage can
// refuse a step that makes it worse without recomputing what the previous stage knew.
#include <cstddef>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher {

struct QualityState {
    std::vector<double> scaled_jacobian;  ///< (hexes): per hex, the minimum over its corners
    std::size_t inverted = 0;             ///< hexes with scaled Jacobian <= 0 (or NaN)
};

/// The state of `mesh` as it is.
[[nodiscard]] QualityState quality_state(const geometry::HexMesh& mesh);

/// Hexes whose value is <= 0 or NaN.
[[nodiscard]] std::size_t count_inverted(const std::vector<double>& scaled_jacobian);
/// Number of hexes with scaled Jacobian <= 0.
[[nodiscard]] std::size_t count_inverted(const geometry::HexMesh& mesh);

}  // namespace dualhex::mesher
