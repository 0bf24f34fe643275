#include "dualhex/geometry/surface_octree.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <tbb/parallel_for.h>

#include "dualhex/geometry/surface_curvature.hpp"
#include "dualhex/geometry/triangle_geometry.hpp"
#include "dualhex/grid/refinement.hpp"
#include "surface_octree_walk.hpp"

namespace dualhex::geometry {

RootCube root_cube(const Eigen::AlignedBox3d& bbox, double margin) {
    const double extent = std::max(bbox.sizes().maxCoeff(), std::numeric_limits<double>::min());
    RootCube r;
    r.size = extent * (1.0 + 2.0 * margin);
    r.origin = bbox.center() - Eigen::Vector3d::Constant(0.5 * r.size);
    return r;
}

std::vector<double> local_thickness(const AabbTree& tree) {
    const auto& s = tree.surface();
    const double diag = tree.bounds().diagonal().norm();
    std::vector<double> out(s.triangles.size(), diag);
    // One ray per triangle, each writing its own entry: the same values for any thread count.
    tbb::parallel_for(std::size_t{0}, s.triangles.size(), [&](std::size_t t) {
        const auto& tri = s.triangles[t];
        const Eigen::Vector3d& a = s.vertices[tri[0]];
        const Eigen::Vector3d& b = s.vertices[tri[1]];
        const Eigen::Vector3d& c = s.vertices[tri[2]];
        const Eigen::Vector3d n = (b - a).cross(c - a);
        if (!(n.norm() > 0)) return;  // degenerate triangle: no normal
        const Eigen::Vector3d centroid = (a + b + c) / 3.0;
        if (auto hit = tree.first_hit(centroid, -n.normalized(), 1e-9 * diag, static_cast<int>(t)))
            out[t] = std::min(diag, hit->t);
    });
    return out;
}

int level_for_size(const RootCube& root, double size) {
    int level = 0;
    while (level < 62 && root.edge(level) > size) ++level;
    return level;
}

std::size_t estimated_leaves(const RootCube& root, double area, int level) {
    // A surface of area A crosses about 1.5 A / h^2 cells of edge h; with their siblings
    // and the grading around them the paired grid had 0.4 (cgal_cube, level 5) to 0.7
    // (gao_bunny_tri, level 6) times 8 * that: the estimate errs on the large side.
    const double h = root.edge(level);
    const double crossing = 1.5 * area / (h * h);
    return static_cast<std::size_t>(std::min(8.0 * crossing, 1e18));
}

namespace {
void check(const SurfaceOctreeOptions& o) {
    if (o.max_depth < 0 || o.max_depth > 20)
        throw std::invalid_argument("surface_octree: max_depth must be in [0, 20], got " + std::to_string(o.max_depth));
    if (o.min_depth < 0 || o.min_depth > o.max_depth)
        throw std::invalid_argument("surface_octree: min_depth must be in [0, max_depth]");
    if (!(o.surface_size >= 0) || !(o.surface_band >= 0) || !(o.thickness_factor >= 0) ||
        !(o.curvature_angle >= 0) || o.curvature_levels < 0 || o.thickness_levels < 0 || !(o.margin >= 0))
        throw std::invalid_argument("surface_octree: size, band, thickness factor, curvature angle and levels, "
                                    "margin must be >= 0");
}
}  // namespace

SurfaceRefinement::SurfaceRefinement(const AabbTree& tree, const SurfaceOctreeOptions& options)
    : tree_(&tree), opt_(options) {
    check(options);
    root_ = root_cube(tree.bounds(), options.margin);
    curvature_cap_ = thickness_cap_ = options.max_depth;
    if (options.surface_size > 0) {
        size_level_ = level_for_size(root_, options.surface_size);
        curvature_cap_ = size_level_ + options.curvature_levels;
        thickness_cap_ = size_level_ + options.thickness_levels;
        const int level = std::min(size_level_, options.max_depth);
        const std::size_t estimate = estimated_leaves(root_, surface_area(tree.surface()), level);
        if (estimate > options.max_leaves)
            throw OctreeTooLarge("surface octree: size " + std::to_string(options.surface_size) + " needs about " +
                                     std::to_string(estimate) + " leaves (level " + std::to_string(level) +
                                     " at the surface), more than the limit " + std::to_string(options.max_leaves),
                                 estimate);
    }
    thickness_ = local_thickness(tree);
    normals_ = area_normals(tree.surface());
}

std::vector<int> SurfaceRefinement::all_triangles() const {
    std::vector<int> all(tree_->surface().triangles.size());
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
    return all;
}

SurfaceRefinement::Decision SurfaceRefinement::decide(const Leaf& cell, const std::vector<int>& parent_near) const {
    // `parent_near` overlap the parent's box grown by the band, so they include everything
    // near this cell.
    const auto& s = tree_->surface();
    const auto overlaps = [&s](const Eigen::AlignedBox3d& box, int t) {
        const auto& tri = s.triangles[t];
        return triangle_box_overlap(box, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]);
    };
    const Eigen::AlignedBox3d box = root_.box(cell);
    Eigen::AlignedBox3d grown = box;
    grown.min().array() -= opt_.surface_band;
    grown.max().array() += opt_.surface_band;
    Decision d;
    std::vector<int> tris;  // d.near includes tris
    for (int t : parent_near) {
        if (overlaps(box, t)) {
            tris.push_back(t);
            d.near.push_back(t);
        } else if (opt_.surface_band > 0 && overlaps(grown, t)) {
            d.near.push_back(t);
        }
    }
    d.crosses = !tris.empty();
    // The split decision (surface_octree.hpp, "Refinement").
    const auto split = [&]() {
        if (cell.level >= opt_.max_depth) return false;
        if (cell.level < opt_.min_depth) return true;
        const double edge = root_.edge(cell.level);
        if (!d.near.empty() && opt_.surface_size > 0 && edge > opt_.surface_size) return true;
        if (tris.empty()) return false;
        if (opt_.thickness_factor > 0 && cell.level < thickness_cap_) {
            double thin = std::numeric_limits<double>::infinity();
            for (int t : tris) thin = std::min(thin, thickness_[t]);
            if (edge > opt_.thickness_factor * thin) return true;
        }
        if (opt_.curvature_angle > 0 && cell.level < curvature_cap_ &&
            normal_spread(tris, normals_) > opt_.curvature_angle) {
            d.by_curvature = true;
            return true;
        }
        return false;
    };
    d.split = split();
    return d;
}

bool surface_crosses(const AabbTree& tree, const RootCube& root, const Leaf& cell) {
    return tree.intersects_box(root.box(cell));
}

SurfaceOctree surface_octree(const AabbTree& tree, const SurfaceOctreeOptions& options) {
    const SurfaceRefinement criterion(tree, options);
    SurfaceOctree out;
    out.root = criterion.root();
    out.size_level = criterion.size_level();
    out.thickness = criterion.thickness();
    detail::WalkResult walk = detail::parallel_walk(criterion);  // the serial walk's leaves, in parallel
    out.crossing_leaves = walk.crossing;
    out.curvature_splits = walk.curvature_splits;
    out.grid = LeafGrid(std::move(walk.leaves), tree.surface().source);
    return out;
}

SurfaceOctree paired_surface_octree(const AabbTree& tree, Balance mode, const SurfaceOctreeOptions& options) {
    SurfaceOctree out = surface_octree(tree, options);
    out.grid = pair(out.grid, mode);
    return out;
}

}  // namespace dualhex::geometry
