#pragma once
// The shape `dualhex mesh` meshes when no surface is given.
#include "dualhex/geometry/surface.hpp"

namespace dualhex::mesher {

/// A torus (major radius 1, minor radius 0.4, 48 x 24 quads split into triangles), closed
/// and oriented outward. source = "<default torus>".
[[nodiscard]] geometry::TriangleSurface default_shape();

}  // namespace dualhex::mesher
