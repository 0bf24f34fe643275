#pragma once
// How much a surface bends inside a region, from its triangles' normals: the refinement
// criterion "the surface is not resolved by this cell" of surface_octree.
//
// normal_spread(tris): the largest angle between a triangle's normal and the area-weighted
// mean normal of the triangles `tris` (the ones crossing a cell). 0 on a flat patch; about
// (cell diagonal / radius) / 2 on a finely triangulated sphere; the half dihedral angle or
// more at a sharp edge (which therefore refines down to the curvature cap); pi when the
// mean normal vanishes, e.g. two opposite sheets of a thin part in one cell. The mean is
// weighted by whole-triangle areas (not the parts inside the cell): an estimate, cheap.
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {

/// Per triangle: its normal scaled by its area (zero for a degenerate triangle).
[[nodiscard]] std::vector<Eigen::Vector3d> area_normals(const TriangleSurface& surface);

/// Total area of the surface.
[[nodiscard]] double surface_area(const TriangleSurface& surface);

/// The normal spread (radians, in [0, pi]) of the triangles `tris` (ids into
/// `area_normals`); degenerate triangles are ignored, 0 if none is left.
[[nodiscard]] double normal_spread(const std::vector<int>& tris, const std::vector<Eigen::Vector3d>& area_normals);

}  // namespace dualhex::geometry
