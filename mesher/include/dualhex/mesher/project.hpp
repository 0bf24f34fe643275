#pragma once
// Stage "project": move the boundary vertices onto the surface.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"

namespace dualhex::mesher {

struct BoundaryProjection {
    std::vector<Eigen::Vector3d> unprojected;  ///< (points): the positions before the stage
    std::vector<char> on_boundary;             ///< (points): 1 on a boundary quad
    std::size_t boundary_vertices = 0;         ///< vertices moved
};

/// In: a hex mesh and the surface's tree. Out: every vertex of a boundary quad (a hex face
/// no other hex shares) moved to its closest surface point; what it was before.
[[nodiscard]] BoundaryProjection project_boundary(geometry::HexMesh& mesh, const geometry::AabbTree& tree);

}  // namespace dualhex::mesher
