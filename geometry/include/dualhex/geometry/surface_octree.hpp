#pragma once
// An octree adapted to a closed surface, as a grid-layer LeafGrid.
//
// Root: the cube centred on the surface's bounding box, edge = largest bbox extent
// * (1 + 2 * margin). Leaf (L,i,j,k) of the grid is the cube root.origin +
// root.size * 2^-L * [i,i+1]x[j,j+1]x[k,k+1].
//
// Refinement: a cell is split iff level < min_depth, or the surface crosses it (some
// triangle overlaps the closed cell) and level < max_depth and the cell edge exceeds
// thickness_factor * (the smallest local thickness of the triangles crossing it).
//
// Local thickness (the feature-size estimate, per triangle): the distance from the
// triangle's centroid to the first surface hit along the inward normal (ray cast with
// the AABB tree; the surface must be oriented outward, which read_surface ensures).
// It measures the thickness of the solid, the feature that matters for the hex mesh
// inside it; it does not see narrow gaps between two parts of the solid (outside), and
// a ray leaving through a near-tangent neighbour can under-estimate (refines more, never
// less). Surfaces with no hit (open or inward oriented) fall back to the bbox diagonal.
//
// The octree is neither balanced nor paired; paired_surface_octree adds
// pair(grid, mode) from the grid layer (least paired + balanced refinement).
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/grid/leaf_grid.hpp"
#include "dualhex/grid/neighbours.hpp"

namespace dualhex::geometry {

/// The embedding of the grid's root cube [0,1]^3 in space.
struct RootCube {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    double size = 1.0;

    /// Corner (i,j,k) of the level-L lattice.
    [[nodiscard]] Eigen::Vector3d point(int level, double i, double j, double k) const {
        return origin + (size / static_cast<double>(std::int64_t{1} << level)) * Eigen::Vector3d(i, j, k);
    }
    [[nodiscard]] Eigen::AlignedBox3d box(const Leaf& cell) const {
        return {point(cell.level, double(cell.i), double(cell.j), double(cell.k)),
                point(cell.level, double(cell.i + 1), double(cell.j + 1), double(cell.k + 1))};
    }
    [[nodiscard]] double edge(int level) const { return size / static_cast<double>(std::int64_t{1} << level); }
};

/// The root cube around `bbox` with `margin` (fraction of the largest extent) on each side.
[[nodiscard]] RootCube root_cube(const Eigen::AlignedBox3d& bbox, double margin);

/// Per-triangle local thickness (see above), indexed like tree.surface().triangles.
[[nodiscard]] std::vector<double> local_thickness(const AabbTree& tree);

struct SurfaceOctreeOptions {
    int max_depth = 7;
    int min_depth = 0;
    double margin = 0.1;
    double thickness_factor = 0.5;
};

struct SurfaceOctree {
    LeafGrid grid;
    RootCube root;
    std::vector<double> thickness;   ///< per triangle (local_thickness)
    std::size_t crossing_leaves = 0; ///< leaves of `grid` the surface crosses (before pairing)
};

/// Octree refined towards the surface (unbalanced, unpaired). Throws std::invalid_argument
/// for max_depth outside [0, 20] or min_depth > max_depth.
[[nodiscard]] SurfaceOctree surface_octree(const AabbTree& tree, const SurfaceOctreeOptions& options = {});

/// surface_octree, then grid = pair(grid, mode): paired and strongly/weakly balanced.
/// crossing_leaves still counts the unbalanced octree's crossing leaves.
[[nodiscard]] SurfaceOctree paired_surface_octree(const AabbTree& tree, Balance mode,
                                                  const SurfaceOctreeOptions& options = {});

/// True iff the surface crosses the closed cell (AABB-tree triangle/box overlap).
[[nodiscard]] bool surface_crosses(const AabbTree& tree, const RootCube& root, const Leaf& cell);

}  // namespace dualhex::geometry
