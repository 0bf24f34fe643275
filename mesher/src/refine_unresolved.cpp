// Stage "refine" (refine_unresolved.hpp): where the core is far from the surface, split
// the octree's leaves once.
#include "dualhex/mesher/refine_unresolved.hpp"

#include <algorithm>
#include <cmath>

#include "dualhex/geometry/surface_distance.hpp"
#include "far_samples.hpp"

namespace dualhex::mesher {

std::vector<UnresolvedPlace> unresolved_places(const geometry::HexMesh& core, const geometry::AabbTree& surface,
                                               double far) {
    const geometry::TriangleSurface boundary = geometry::boundary_triangles(core);
    std::vector<UnresolvedPlace> samples;
    if (boundary.triangles.empty()) {  // an empty core resolves nothing
        for (const Eigen::Vector3d& p : detail::surface_samples(surface.surface())) samples.push_back({p, far});
    } else {  // input samples far from the core where they are; core samples at their input point
        const geometry::AabbTree to_core(boundary);
        for (const auto& f : detail::far_samples(surface.surface(), to_core, far)) samples.push_back({f.point, f.distance});
        for (const auto& f : detail::far_samples(boundary, surface, far)) samples.push_back({f.closest, f.distance});
    }
    std::stable_sort(samples.begin(), samples.end(),
                     [](const UnresolvedPlace& a, const UnresolvedPlace& b) { return a.distance > b.distance; });
    std::vector<UnresolvedPlace> places;  // one per ball: the farthest sample stands for its neighbours
    for (const UnresolvedPlace& p : samples) {
        const bool known = std::any_of(places.begin(), places.end(), [&](const UnresolvedPlace& q) {
            return (q.point - p.point).norm() <= q.distance;
        });
        if (!known) places.push_back(p);
    }
    return places;
}

namespace {

// The level of the leaf containing p (the finest level's lattice cell located), -1 outside.
int level_at(const LeafGrid& octree, const geometry::RootCube& root, const Eigen::Vector3d& p) {
    const int level = octree.max_level();
    const double edge = root.edge(level);
    Leaf cell{level, 0, 0, 0};
    const Eigen::Vector3d rel = (p - root.origin) / edge;
    const auto at = [&](double x) { return static_cast<std::int64_t>(std::floor(x)); };
    cell.i = at(rel.x());
    cell.j = at(rel.y());
    cell.k = at(rel.z());
    if (!cell.valid()) return -1;
    const auto leaf = octree.locate(cell);
    return leaf ? octree.leaf(*leaf).level : -1;
}

bool meets_ball(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& centre, double radius) {
    return box.squaredExteriorDistance(centre) <= radius * radius;
}

}  // namespace

LocalRefinement refine_at_places(const LeafGrid& octree, const geometry::RootCube& root,
                                 const std::vector<UnresolvedPlace>& places, int max_depth, double max_radius) {
    std::vector<int> place_level;
    for (const UnresolvedPlace& p : places) place_level.push_back(level_at(octree, root, p.point));
    LocalRefinement out;
    std::vector<Leaf> leaves;
    leaves.reserve(octree.size());
    for (const Leaf& leaf : octree.leaves()) {
        bool split = false;
        if (leaf.level < max_depth) {
            const Eigen::AlignedBox3d box = root.box(leaf);
            for (std::size_t n = 0; n < places.size() && !split; ++n)
                split = leaf.level <= place_level[n] && meets_ball(box, places[n].point, std::min(places[n].distance, max_radius));
        }
        if (!split) {
            leaves.push_back(leaf);
            continue;
        }
        ++out.split;
        for (const Leaf& child : children(leaf)) leaves.push_back(child);
    }
    out.grid = LeafGrid(std::move(leaves), octree.source());
    return out;
}

}  // namespace dualhex::mesher
