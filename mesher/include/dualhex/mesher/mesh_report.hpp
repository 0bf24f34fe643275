#pragma once
// Stage "report": the figures of a finished hex mesh that the pipeline reports.
#include <cstddef>
#include <map>

#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher {

/// Interior edges (not an edge of a boundary quad) with a number of hexes != 4:
/// valence -> count.
[[nodiscard]] std::map<int, std::size_t> interior_singular_edge_valences(const geometry::HexMesh& mesh);

}  // namespace dualhex::mesher
