#include "dualhex/geometry/aabb_tree.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "dualhex/geometry/parallel_each.hpp"
#include "dualhex/geometry/triangle_geometry.hpp"

namespace dualhex::geometry {

using Eigen::AlignedBox3d;
using Eigen::Vector3d;

namespace {
constexpr int kLeafSize = 4;

// Slab test: the parameter interval [t0, t1] of the ray inside the box, if any.
bool ray_box(const AlignedBox3d& box, const Vector3d& o, const Vector3d& inv_dir, double t_max, double& t_enter) {
    double t0 = 0, t1 = t_max;
    for (int a = 0; a < 3; ++a) {
        double ta = (box.min()[a] - o[a]) * inv_dir[a];
        double tb = (box.max()[a] - o[a]) * inv_dir[a];
        if (ta > tb) std::swap(ta, tb);
        if (std::isnan(ta) || std::isnan(tb)) {  // 0 * inf: origin on the slab plane
            if (o[a] < box.min()[a] || o[a] > box.max()[a]) return false;
            continue;
        }
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    t_enter = t0;
    return true;
}
}  // namespace

AabbTree::AabbTree(TriangleSurface surface) : surface_(std::move(surface)) {
    if (surface_.triangles.empty()) throw SurfaceError(surface_.source, "AABB tree of an empty surface");
    const auto n = static_cast<int>(surface_.triangles.size());
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    centroids_.resize(n);
    for (int t = 0; t < n; ++t) {
        const auto& tri = surface_.triangles[t];
        centroids_[t] = (surface_.vertices[tri[0]] + surface_.vertices[tri[1]] + surface_.vertices[tri[2]]) / 3.0;
    }
    nodes_.reserve(2 * n / kLeafSize + 2);
    build(0, n);
}

int AabbTree::build(int first, int count) {
    const int id = static_cast<int>(nodes_.size());
    nodes_.push_back({});
    AlignedBox3d box, cbox;
    for (int n = first; n < first + count; ++n) {
        for (int c : surface_.triangles[order_[n]]) box.extend(surface_.vertices[c]);
        cbox.extend(centroids_[order_[n]]);
    }
    nodes_[id].box = box;
    if (count <= kLeafSize) {
        nodes_[id].first = first;
        nodes_[id].count = count;
        return id;
    }
    int axis = 0;
    cbox.sizes().maxCoeff(&axis);
    const int mid = first + count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + first + count,
                     [&](int a, int b) { return centroids_[a][axis] < centroids_[b][axis]; });
    const int left = build(first, mid - first);
    const int right = build(mid, first + count - mid);
    nodes_[id].left = left;
    nodes_[id].right = right;
    return id;
}

ClosestPoint AabbTree::closest_point(const Vector3d& p) const {
    return closest_point(p, std::numeric_limits<double>::infinity());
}

ClosestPoint AabbTree::closest_point(const Vector3d& p, double max_squared_distance) const {
    ClosestPoint best;
    best.squared_distance = max_squared_distance;
    best.triangle = -1;
    // A fixed stack (no allocation per query): the median split keeps the depth below
    // log2(triangles) + 2, and each level pushes at most 2 nodes.
    struct Entry {
        int node;
        double squared_distance;  // of the node's box, computed when pushed
    };
    std::array<Entry, 160> stack;
    int top = 0;
    stack[top++] = {0, nodes_.front().box.squaredExteriorDistance(p)};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.squared_distance >= best.squared_distance) continue;
        const Node& node = nodes_[e.node];
        if (node.left < 0) {
            for (int n = node.first; n < node.first + node.count; ++n) {
                const auto& tri = surface_.triangles[order_[n]];
                const Vector3d q = closest_point_on_triangle(p, surface_.vertices[tri[0]], surface_.vertices[tri[1]],
                                                             surface_.vertices[tri[2]]);
                const double d = (q - p).squaredNorm();
                if (d < best.squared_distance) best = {q, d, order_[n]};
            }
            continue;
        }
        const double dl = nodes_[node.left].box.squaredExteriorDistance(p);
        const double dr = nodes_[node.right].box.squaredExteriorDistance(p);
        // push the farther child first so the nearer one is visited first
        if (dl < dr) {
            stack[top++] = {node.right, dr};
            stack[top++] = {node.left, dl};
        } else {
            stack[top++] = {node.left, dl};
            stack[top++] = {node.right, dr};
        }
    }
    return best;
}

// Calls visit(id) for every triangle overlapping the box until visit returns true;
// returns whether it did.
template <class Visit>
bool AabbTree::box_walk(const AlignedBox3d& box, Visit&& visit) const {
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const Node& node = nodes_[stack.back()];
        stack.pop_back();
        if (!node.box.intersects(box)) continue;
        if (node.left < 0) {
            for (int n = node.first; n < node.first + node.count; ++n) {
                const auto& tri = surface_.triangles[order_[n]];
                if (triangle_box_overlap(box, surface_.vertices[tri[0]], surface_.vertices[tri[1]],
                                         surface_.vertices[tri[2]]) &&
                    visit(order_[n]))
                    return true;
            }
            continue;
        }
        stack.push_back(node.left);
        stack.push_back(node.right);
    }
    return false;
}

bool AabbTree::intersects_box(const AlignedBox3d& box) const {
    return box_walk(box, [](int) { return true; });
}

std::vector<int> AabbTree::triangles_in_box(const AlignedBox3d& box) const {
    std::vector<int> out;
    box_walk(box, [&](int id) {
        out.push_back(id);
        return false;
    });
    return out;
}

template <class Visit>
void AabbTree::ray_walk(const Vector3d& origin, const Vector3d& dir, double t_max_init, Visit&& visit) const {
    const Vector3d inv = dir.cwiseInverse();
    double t_max = t_max_init;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const Node& node = nodes_[stack.back()];
        stack.pop_back();
        double t_enter = 0;
        if (!ray_box(node.box, origin, inv, t_max, t_enter)) continue;
        if (node.left < 0) {
            for (int n = node.first; n < node.first + node.count; ++n) visit(order_[n], t_max);
            continue;
        }
        stack.push_back(node.left);
        stack.push_back(node.right);
    }
}

std::optional<RayHit> AabbTree::first_hit(const Vector3d& origin, const Vector3d& dir, double t_min, int ignore) const {
    std::optional<RayHit> best;
    ray_walk(origin, dir, std::numeric_limits<double>::infinity(), [&](int t, double& t_max) {
        if (t == ignore) return;
        const auto& tri = surface_.triangles[t];
        const auto hit = ray_triangle(origin, dir, surface_.vertices[tri[0]], surface_.vertices[tri[1]],
                                      surface_.vertices[tri[2]], t_min);
        if (hit && hit->t < t_max) {
            t_max = hit->t;
            best = RayHit{hit->t, t, origin + hit->t * dir};
        }
    });
    return best;
}

std::vector<RayHit> AabbTree::all_hits(const Vector3d& origin, const Vector3d& dir, double t_min) const {
    std::vector<RayHit> hits;
    ray_walk(origin, dir, std::numeric_limits<double>::infinity(), [&](int t, double&) {
        const auto& tri = surface_.triangles[t];
        const auto hit = ray_triangle(origin, dir, surface_.vertices[tri[0]], surface_.vertices[tri[1]],
                                      surface_.vertices[tri[2]], t_min);
        if (hit) hits.push_back({hit->t, t, origin + hit->t * dir});
    });
    std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) { return a.t < b.t; });
    return hits;
}

std::vector<ClosestPoint> closest_points(const AabbTree& tree, const std::vector<Eigen::Vector3d>& points) {
    std::vector<ClosestPoint> out(points.size());
    parallel_each(points.size(), 256, [&](std::size_t i) { out[i] = tree.closest_point(points[i]); });
    return out;
}

std::vector<double> distances(const AabbTree& tree, const std::vector<Eigen::Vector3d>& points) {
    std::vector<double> out(points.size());
    parallel_each(points.size(), 256, [&](std::size_t i) { out[i] = std::sqrt(tree.squared_distance(points[i])); });
    return out;
}

}  // namespace dualhex::geometry
