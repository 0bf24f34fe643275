#pragma once
// Internal: the edges of a complex from its face loops (CellComplex's constructor).
//
// Edges are the distinct unordered vertex pairs consecutive in some face loop, numbered by
// smaller endpoint, then by first appearance (corner order). The corners are bucketed by
// smaller endpoint with a stable parallel counting sort (one count row per block of
// faces), the buckets deduplicated in parallel and numbered by a prefix sum: every step's
// result is fixed by the input alone, so the numbering is the same for any thread count.
#include <array>
#include <cstdint>
#include <vector>

#include "dualhex/topology/handles.hpp"

namespace dualhex::detail {

struct DerivedEdges {
    std::vector<EdgeHandle> face_edges;  // parallel to the face loops
    std::vector<std::array<VertexHandle, 2>> edge_vertices;
};

[[nodiscard]] DerivedEdges derive_edges(std::size_t n_vertices, const std::vector<std::uint32_t>& face_offsets,
                                        const std::vector<VertexHandle>& face_loops);

}  // namespace dualhex::detail
