#include "dualhex/geometry/surface_octree.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

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

namespace {
struct Builder {
    const AabbTree& tree;
    const RootCube& root;
    const SurfaceOctreeOptions& opt;
    const std::vector<double>& thickness;
    std::vector<Leaf> leaves;
    std::size_t crossing = 0;

    void visit(const Leaf& cell, const std::vector<int>& parent_tris) {
        const auto& s = tree.surface();
        const Eigen::AlignedBox3d box = root.box(cell);
        std::vector<int> tris;
        double thin = std::numeric_limits<double>::infinity();
        for (int t : parent_tris) {
            const auto& tri = s.triangles[t];
            if (triangle_box_overlap(box, s.vertices[tri[0]], s.vertices[tri[1]], s.vertices[tri[2]])) {
                tris.push_back(t);
                thin = std::min(thin, thickness[t]);
            }
        }
        const bool crossed = !tris.empty();
        const bool split = cell.level < opt.min_depth ||
                           (crossed && cell.level < opt.max_depth && root.edge(cell.level) > opt.thickness_factor * thin);
        if (!split) {
            leaves.push_back(cell);
            crossing += crossed ? 1 : 0;
            return;
        }
        for (const Leaf& child : children(cell)) visit(child, tris);
    }
};
}  // namespace

bool surface_crosses(const AabbTree& tree, const RootCube& root, const Leaf& cell) {
    return tree.intersects_box(root.box(cell));
}

SurfaceOctree surface_octree(const AabbTree& tree, const SurfaceOctreeOptions& options) {
    if (options.max_depth < 0 || options.max_depth > 20)
        throw std::invalid_argument("surface_octree: max_depth must be in [0, 20], got " +
                                    std::to_string(options.max_depth));
    if (options.min_depth < 0 || options.min_depth > options.max_depth)
        throw std::invalid_argument("surface_octree: min_depth must be in [0, max_depth]");
    SurfaceOctree out;
    out.root = root_cube(tree.bounds(), options.margin);
    out.thickness = local_thickness(tree);
    Builder b{tree, out.root, options, out.thickness, {}, 0};
    std::vector<int> all(tree.surface().triangles.size());
    for (std::size_t t = 0; t < all.size(); ++t) all[t] = static_cast<int>(t);
    b.visit(Leaf{}, all);
    out.crossing_leaves = b.crossing;
    out.grid = LeafGrid(std::move(b.leaves), tree.surface().source);
    return out;
}

SurfaceOctree paired_surface_octree(const AabbTree& tree, Balance mode, const SurfaceOctreeOptions& options) {
    SurfaceOctree out = surface_octree(tree, options);
    out.grid = pair(out.grid, mode);
    return out;
}

}  // namespace dualhex::geometry
