#include "dualhex/geometry/surface_octree.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "dualhex/geometry/surface_curvature.hpp"
#include "dualhex/geometry/triangle_geometry.hpp"
#include "dualhex/grid/refinement.hpp"

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
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        const auto& tri = s.triangles[t];
        const Eigen::Vector3d& a = s.vertices[tri[0]];
        const Eigen::Vector3d& b = s.vertices[tri[1]];
        const Eigen::Vector3d& c = s.vertices[tri[2]];
        const Eigen::Vector3d n = (b - a).cross(c - a);
        if (!(n.norm() > 0)) continue;  // degenerate triangle: no normal
        const Eigen::Vector3d centroid = (a + b + c) / 3.0;
        if (auto hit = tree.first_hit(centroid, -n.normalized(), 1e-9 * diag, static_cast<int>(t)))
            out[t] = std::min(diag, hit->t);
    }
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
struct Builder {
    const AabbTree& tree;
    const RootCube& root;
    const SurfaceOctreeOptions& opt;
    const std::vector<double>& thickness;
    const std::vector<Eigen::Vector3d>& normals;  // area-weighted, per triangle
    int curvature_cap = 0, thickness_cap = 0;
    std::vector<Leaf> leaves;
    std::size_t crossing = 0, curvature_splits = 0;

    bool overlaps(const Eigen::AlignedBox3d& box, int t) const {
        const auto& s = tree.surface();
        const auto& tri = s.triangles[t];
        return triangle_box_overlap(box, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]]);
    }

    // The split decision (surface_octree.hpp, "Refinement"); `tris` cross the cell, `near`
    // is true if some triangle lies within the band.
    bool split(const Leaf& cell, const std::vector<int>& tris, bool near) {
        if (cell.level >= opt.max_depth) return false;
        if (cell.level < opt.min_depth) return true;
        const double edge = root.edge(cell.level);
        if ((near || !tris.empty()) && opt.surface_size > 0 && edge > opt.surface_size) return true;
        if (tris.empty()) return false;
        if (opt.thickness_factor > 0 && cell.level < thickness_cap) {
            double thin = std::numeric_limits<double>::infinity();
            for (int t : tris) thin = std::min(thin, thickness[t]);
            if (edge > opt.thickness_factor * thin) return true;
        }
        if (opt.curvature_angle > 0 && cell.level < curvature_cap &&
            normal_spread(tris, normals) > opt.curvature_angle) {
            ++curvature_splits;
            return true;
        }
        return false;
    }

    // `parent_near`: the triangles within the band of the parent (all of them overlap the
    // parent's box grown by the band, so they include everything near this cell).
    void visit(const Leaf& cell, const std::vector<int>& parent_near) {
        const Eigen::AlignedBox3d box = root.box(cell);
        Eigen::AlignedBox3d grown = box;
        grown.min().array() -= opt.surface_band;
        grown.max().array() += opt.surface_band;
        std::vector<int> near, tris;  // near includes tris
        for (int t : parent_near) {
            if (overlaps(box, t)) {
                tris.push_back(t);
                near.push_back(t);
            } else if (opt.surface_band > 0 && overlaps(grown, t)) {
                near.push_back(t);
            }
        }
        if (!split(cell, tris, !near.empty())) {
            leaves.push_back(cell);
            crossing += tris.empty() ? 0 : 1;
            return;
        }
        if (leaves.size() + 8 > opt.max_leaves)
            throw OctreeTooLarge("surface octree: more than " + std::to_string(opt.max_leaves) +
                                     " leaves (the size, thickness or curvature criteria ask for too fine cells)",
                                 leaves.size() + 8);
        for (const Leaf& child : children(cell)) visit(child, near);
    }
};

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

bool surface_crosses(const AabbTree& tree, const RootCube& root, const Leaf& cell) {
    return tree.intersects_box(root.box(cell));
}

SurfaceOctree surface_octree(const AabbTree& tree, const SurfaceOctreeOptions& options) {
    check(options);
    SurfaceOctree out;
    out.root = root_cube(tree.bounds(), options.margin);
    int curvature_cap = options.max_depth, thickness_cap = options.max_depth;
    if (options.surface_size > 0) {
        out.size_level = level_for_size(out.root, options.surface_size);
        curvature_cap = out.size_level + options.curvature_levels;
        thickness_cap = out.size_level + options.thickness_levels;
        const int level = std::min(out.size_level, options.max_depth);
        const std::size_t estimate = estimated_leaves(out.root, surface_area(tree.surface()), level);
        if (estimate > options.max_leaves)
            throw OctreeTooLarge("surface octree: size " + std::to_string(options.surface_size) + " needs about " +
                                     std::to_string(estimate) + " leaves (level " + std::to_string(level) +
                                     " at the surface), more than the limit " + std::to_string(options.max_leaves),
                                 estimate);
    }
    out.thickness = local_thickness(tree);
    const std::vector<Eigen::Vector3d> normals = area_normals(tree.surface());
    Builder b{tree, out.root, options, out.thickness, normals, curvature_cap, thickness_cap, {}, 0, 0};
    std::vector<int> all(tree.surface().triangles.size());
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
    b.visit(Leaf{}, all);
    out.crossing_leaves = b.crossing;
    out.curvature_splits = b.curvature_splits;
    out.grid = LeafGrid(std::move(b.leaves), tree.surface().source);
    return out;
}

SurfaceOctree paired_surface_octree(const AabbTree& tree, Balance mode, const SurfaceOctreeOptions& options) {
    SurfaceOctree out = surface_octree(tree, options);
    out.grid = pair(out.grid, mode);
    return out;
}

}  // namespace dualhex::geometry
