#pragma once
// An octree adapted to a closed surface, as a grid-layer LeafGrid.
//
// Root: the cube centred on the surface's bounding box, edge = largest bbox extent
// * (1 + 2 * margin). Leaf (L,i,j,k) of the grid is the cube root.origin +
// root.size * 2^-L * [i,i+1]x[j,j+1]x[k,k+1].
//
// Refinement: a cell is split iff level < max_depth (a cap, nothing else stops at it) and
//   - level < min_depth, or
//   - size: the surface crosses it (some triangle overlaps the closed cell), or passes
//     within `surface_band` of it, and its edge exceeds surface_size, or
//   - thickness: the surface crosses it, its level is below the thickness cap and its edge
//     exceeds thickness_factor * (the smallest local thickness of the triangles crossing
//     it), or
//   - curvature: the surface crosses it, its level is below the curvature cap and the
//     normal spread of the triangles crossing it (surface_curvature.hpp) exceeds
//     curvature_angle: the surface bends too much over the cell, has a sharp feature in
//     it, or two sheets of a thin part cross it. The cap is size_level + curvature_levels
//     (size_level: the first level whose edge is <= surface_size; max_depth without a size).
// A zero surface_size, thickness_factor or curvature_angle turns that criterion off.
//
// Size bound: refinement stops with OctreeTooLarge once more than max_leaves leaves would
// exist; with a surface_size, the leaves it needs are estimated first (from the surface's
// area) and an estimate above max_leaves is refused before any work.
//
// Local thickness (the feature-size estimate, per triangle): the distance from the
// triangle's centroid to the first surface hit along the inward normal (ray cast with
// the AABB tree; the surface must be oriented outward, which read_surface ensures).
// It measures the thickness of the solid, the feature that matters for the hex mesh
// inside it; it does not see narrow gaps between two parts of the solid (outside), and
// a ray leaving through a near-tangent neighbour can under-estimate (refines more, never
// less). Surfaces with no hit (open or inward oriented) fall back to the bbox diagonal.
//
// Built in parallel (oneTBB; src/surface_octree_walk.cpp): the 8 subtrees of every split
// cell above level 4 are walked by tasks and concatenated in child order, so the leaves are
// the serial recursion's, in its depth-first (Morton) order, for any number of threads;
// the leaf budget refuses exactly as the serial walk does (the walk falls back to it past
// the budget). The local thickness's ray casts run in parallel too.
//
// The octree is neither balanced nor paired; paired_surface_octree adds
// pair(grid, mode) from the grid layer (least paired + balanced refinement).
#include <cstddef>
#include <stdexcept>
#include <string>
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
    double surface_size = 0;       ///< target cell edge at the surface (model units), 0: none
    double surface_band = 0;       ///< cells this close to the surface (model units) get surface_size too
    double curvature_angle = 0;    ///< max normal spread in a crossing cell (radians), 0: off
    int curvature_levels = 2;      ///< curvature refines at most this many levels below size_level
    int thickness_levels = 3;      ///< thickness refines at most this many levels below size_level
    std::size_t max_leaves = 20'000'000;
};

/// A refinement that would exceed SurfaceOctreeOptions::max_leaves.
class OctreeTooLarge : public std::runtime_error {
public:
    OctreeTooLarge(const std::string& message, std::size_t leaves)
        : std::runtime_error(message), leaves_(leaves) {}
    /// The estimate (or the count reached) that was refused.
    [[nodiscard]] std::size_t leaves() const { return leaves_; }

private:
    std::size_t leaves_;
};

/// The first level whose cell edge is <= size (0 if the root is), for size > 0.
[[nodiscard]] int level_for_size(const RootCube& root, double size);

/// Estimated leaves of the paired grid refined to `level` at the surface (`area` its area):
/// the crossing cells (about 1.5 area / edge^2), with their siblings and the grading
/// around them (a factor measured on the shared models, see surface_octree.cpp).
[[nodiscard]] std::size_t estimated_leaves(const RootCube& root, double area, int level);

struct SurfaceOctree {
    LeafGrid grid;
    RootCube root;
    std::vector<double> thickness;   ///< per triangle (local_thickness)
    std::size_t crossing_leaves = 0; ///< leaves of `grid` the surface crosses (before pairing)
    int size_level = -1;             ///< level_for_size(surface_size), uncapped; -1 without a size
    std::size_t curvature_splits = 0;  ///< cells split by the curvature criterion alone
};

/// The refinement criterion of surface_octree ("Refinement" above), callable per cell, so
/// that another octree builder (the distributed mesher's p8est refine callback) refines
/// exactly like surface_octree. A cell's decision depends on its parent's `near`
/// triangles (those overlapping the parent's box grown by the band; all triangles for the
/// root): surface_octree filters them down the recursion, and so must every caller, for
/// the same floating-point box tests and so the same octree.
class SurfaceRefinement {
public:
    /// Checks the options, computes the root cube, the thickness and the normals, and
    /// refuses (OctreeTooLarge) a size whose leaf estimate exceeds max_leaves; the same
    /// errors as surface_octree.
    SurfaceRefinement(const AabbTree& tree, const SurfaceOctreeOptions& options);

    struct Decision {
        bool split = false;
        bool crosses = false;       ///< some triangle overlaps the closed cell
        bool by_curvature = false;  ///< split by the curvature criterion alone
        std::vector<int> near;      ///< the cell's near triangles (its children's parent_near)
    };
    /// The decision for `cell` given its parent's near triangles.
    [[nodiscard]] Decision decide(const Leaf& cell, const std::vector<int>& parent_near) const;
    /// Every triangle index: the root's parent_near.
    [[nodiscard]] std::vector<int> all_triangles() const;

    [[nodiscard]] const RootCube& root() const { return root_; }
    [[nodiscard]] const SurfaceOctreeOptions& options() const { return opt_; }
    [[nodiscard]] int size_level() const { return size_level_; }
    [[nodiscard]] const std::vector<double>& thickness() const { return thickness_; }

private:
    const AabbTree* tree_;
    SurfaceOctreeOptions opt_;
    RootCube root_;
    int size_level_ = -1, curvature_cap_ = 0, thickness_cap_ = 0;
    std::vector<double> thickness_;
    std::vector<Eigen::Vector3d> normals_;  // area-weighted, per triangle
};

/// Octree refined towards the surface (unbalanced, unpaired). Throws std::invalid_argument
/// for max_depth outside [0, 20], min_depth > max_depth, a negative size, band, factor,
/// angle or levels; OctreeTooLarge beyond max_leaves.
[[nodiscard]] SurfaceOctree surface_octree(const AabbTree& tree, const SurfaceOctreeOptions& options = {});

/// surface_octree, then grid = pair(grid, mode): paired and strongly/weakly balanced.
/// crossing_leaves still counts the unbalanced octree's crossing leaves.
[[nodiscard]] SurfaceOctree paired_surface_octree(const AabbTree& tree, Balance mode,
                                                  const SurfaceOctreeOptions& options = {});

/// True iff the surface crosses the closed cell (AABB-tree triangle/box overlap).
[[nodiscard]] bool surface_crosses(const AabbTree& tree, const RootCube& root, const Leaf& cell);

}  // namespace dualhex::geometry
