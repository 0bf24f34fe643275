#pragma once
// Stage "pad": one layer of hexes (a pillow layer) between the core and the surface.
//
// Input : the core (points (N, 3), hexes (M, 8) VTK order) whose boundary quads
//         (faces of one hex, outward) form a closed surface, the surface's tree.
// Output: PadResult — the padded mesh: the core's N points and M hexes unchanged (same
//         ids, so the core's interior valences are unchanged), then one new point v'
//         per core boundary vertex v (ids N .. N+B-1, in increasing order of v) on the
//         surface, then one hex (a, b, c, d, a', b', c', d') per core boundary quad
//         (a, b, c, d): the quad is its bottom, its image the top, so with the quad
//         outward it has positive orientation in VTK_HEXAHEDRON order. Topology from ids
//         only: v' is shared because it is looked up by v's id, never by position. So
//         the padded boundary is the core boundary's image, the same surface (manifold
//         iff the core's is). Roles: v' Surface, all others Interior.
//
// Placement of v' (after Marechal 2009 and Gao et al. 2019, see mesher/README.md): along
// a smoothed vertex normal n (area-weighted quad normals, `normal_smoothing` rounds of
// averaging with the boundary neighbours, which turns the staircase's axis-aligned
// normals towards the surface's): v' is the first surface hit of the ray v + t n when
// t <= ray_limit * (d + h) (d: v's distance to the surface, h: the mean length of v's
// boundary edges), else the closest surface point of v (a concave spot, where the ray may
// run far). Either way v' is on the surface. Then, at the outer points of inverted pad
// hexes, the other candidate (closest point / ray hit) is taken where it inverts fewer
// hexes at that point (up to 3 rounds).
#include <cstddef>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

struct PadOptions {
    /// Sweeps of core_boundary_smooth.hpp the pipeline runs on the core before the pad, and
    /// their quality floor for core hexes. Off (0) by default: it halves the bad pad hexes
    /// after the pad but not at the end of the pipeline (mesher/README.md, measured).
    int core_smoothing = 0;
    double core_smoothing_floor = 0.5;
    int normal_smoothing = 3;
    double ray_limit = 2.0;
};

struct PadResult {
    geometry::HexMesh mesh;
    VertexConstraints constraints;  ///< (points): Surface for the new points
    std::size_t core_points = 0, core_hexes = 0;
    std::size_t pad_hexes = 0, surface_vertices = 0;
    std::size_t by_ray = 0, by_closest_point = 0;  ///< how the surface points were first placed
    std::size_t switched = 0;  ///< then switched to the other candidate (fewer inverted hexes there)
};

/// Throws std::invalid_argument if the core has no boundary quad.
[[nodiscard]] PadResult pad_layer(const geometry::HexMesh& core, const geometry::AabbTree& tree,
                                  const PadOptions& options = {});

}  // namespace dualhex::mesher
