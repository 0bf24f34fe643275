#pragma once
// Inside/outside of a closed surface.
//
// is_inside: ray parity along 5 fixed, "generic" directions (components irrational-ish,
// none axis-aligned), majority vote. A ray that grazes an edge or vertex may miscount,
// but one point cannot make 3 of 5 generic rays degenerate except on the surface
// itself. Points outside the bounding box are outside without a ray. Cost: 5 ray casts.
//
// winding_number: the generalized winding number (sum of signed solid angles / 4pi),
// exact up to rounding, O(F) per point — the reference the tests compare with. ~1 inside,
// ~0 outside for an outward-oriented closed surface.
#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {

[[nodiscard]] bool is_inside(const AabbTree& tree, const Eigen::Vector3d& p);

/// Number of the 5 rays from p with an odd number of hits (is_inside: >= 3).
[[nodiscard]] int inside_votes(const AabbTree& tree, const Eigen::Vector3d& p);

[[nodiscard]] double winding_number(const TriangleSurface& s, const Eigen::Vector3d& p);

}  // namespace dualhex::geometry
