#pragma once
// Two-sided distance between the boundary of a hex mesh and a triangle surface
// (issue 12: the pipeline's one-sided, sampled `hausdorff` under-reports).
//
// Stage  : report (after projection / smoothing / untangling), or any time after.
// Input  : mesh    — a HexMesh (points (N, 3), hexes (M, 8), VTK order); its boundary
//                    quads (faces of exactly one hex) are split along the 0-2 diagonal
//                    into two triangles each;
//          surface — an AabbTree over the input surface (the one the mesh should match);
//          options — sample spacing (relative to the surface's bbox diagonal).
// Output : SurfaceDistance — per direction the area-weighted mean and the max (the
//          directed Hausdorff distance, up to the sampling) of the distance from points
//          of one side to the other, absolute; the symmetric values; the bbox diagonal
//          (divide by it for relative values); the share of the mesh's boundary vertices
//          within on_surface_tolerance * diagonal of the surface.
// Errors : std::invalid_argument for a mesh without boundary quads or bad options.
//
// Samples on each triangle of either side: the barycentric grid with n + 1 points per
// edge, n = ceil(longest edge / spacing) clamped to [1, max_subdivisions]; so every
// vertex and every triangle of both sides is sampled, and the max is exact wherever a
// vertex is the farthest point (e.g. between piecewise-linear surfaces whose farthest
// point is a corner). Distances to the other side are exact point-to-triangle
// distances through an AabbTree (built here over the mesh's boundary triangles).
// A sample's weight is its triangle's area / the triangle's sample count.
#include <algorithm>
#include <cstddef>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::geometry {

struct SurfaceDistanceOptions {
    double sample_spacing = 0.005;       ///< relative to the surface's bbox diagonal, > 0
    int max_subdivisions = 64;           ///< per triangle edge, >= 1
    double on_surface_tolerance = 1e-6;  ///< relative to the diagonal
};

struct DirectedDistance {
    std::size_t samples = 0;
    double mean = 0;  ///< area-weighted
    double max = 0;
    Eigen::Vector3d farthest = Eigen::Vector3d::Zero();  ///< the sample at the max
};

struct SurfaceDistance {
    double diagonal = 0;               ///< of the surface's bounding box
    DirectedDistance mesh_to_surface;  ///< from the hex boundary
    DirectedDistance surface_to_mesh;  ///< from the input surface
    std::size_t boundary_vertices = 0;
    double share_vertices_on_surface = 0;
    [[nodiscard]] double max() const { return std::max(mesh_to_surface.max, surface_to_mesh.max); }
    [[nodiscard]] double mean() const { return 0.5 * (mesh_to_surface.mean + surface_to_mesh.mean); }
    [[nodiscard]] double relative(double d) const { return diagonal > 0 ? d / diagonal : 0; }
};

/// The boundary quads of `mesh` as triangles (0-1-2, 0-2-3), outward; vertices = all
/// points of the mesh (unused ones included: AabbTree does not mind).
[[nodiscard]] TriangleSurface boundary_triangles(const HexMesh& mesh);

[[nodiscard]] SurfaceDistance surface_distance(const HexMesh& mesh, const AabbTree& surface,
                                               const SurfaceDistanceOptions& options = {});

}  // namespace dualhex::geometry
