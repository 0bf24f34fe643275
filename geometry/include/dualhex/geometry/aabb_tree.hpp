#pragma once
// AabbTree: a bounding-volume hierarchy over the triangles of a surface.
//
// Input : a TriangleSurface (copied; the tree owns it).
// Output: queries — closest point / squared distance, whether (and which) triangles
//         overlap a box (does the surface cross this cell), ray casts (first hit, all
//         hits). Build: median split of triangle centroids along the longest axis,
//         <= 4 triangles per leaf; O(F log F).
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {

struct ClosestPoint {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    double squared_distance = 0;
    int triangle = -1;
};

struct RayHit {
    double t = 0;          ///< hit point = origin + t * direction
    int triangle = -1;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

class AabbTree {
public:
    explicit AabbTree(TriangleSurface surface);

    [[nodiscard]] const TriangleSurface& surface() const { return surface_; }
    [[nodiscard]] const Eigen::AlignedBox3d& bounds() const { return nodes_.front().box; }
    [[nodiscard]] std::size_t node_count() const { return nodes_.size(); }

    /// The surface point nearest to p (ties: any). Precondition: non-empty surface.
    [[nodiscard]] ClosestPoint closest_point(const Eigen::Vector3d& p) const;
    /// The same, searching only closer than sqrt(max_squared_distance): if no triangle is,
    /// squared_distance == max_squared_distance and triangle == -1 (point undefined).
    [[nodiscard]] ClosestPoint closest_point(const Eigen::Vector3d& p, double max_squared_distance) const;
    [[nodiscard]] double squared_distance(const Eigen::Vector3d& p) const { return closest_point(p).squared_distance; }

    /// True iff some (closed) triangle overlaps the (closed) box.
    [[nodiscard]] bool intersects_box(const Eigen::AlignedBox3d& box) const;
    /// All triangles overlapping the box (ids, unsorted).
    [[nodiscard]] std::vector<int> triangles_in_box(const Eigen::AlignedBox3d& box) const;

    /// Nearest hit with t > t_min of the ray origin + t*dir, skipping triangle `ignore`.
    [[nodiscard]] std::optional<RayHit> first_hit(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                                  double t_min = 0.0, int ignore = -1) const;
    /// Every hit with t > t_min, sorted by t (a ray through an edge may hit both triangles).
    [[nodiscard]] std::vector<RayHit> all_hits(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                                               double t_min = 0.0) const;

private:
    struct Node {
        Eigen::AlignedBox3d box;
        int first = 0, count = 0;  // leaf: triangles order_[first, first+count)
        int left = -1, right = -1;  // inner: children
    };
    int build(int first, int count);
    template <class Visit>
    bool box_walk(const Eigen::AlignedBox3d& box, Visit&& visit) const;
    template <class Visit>
    void ray_walk(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, double t_max_init, Visit&& visit) const;

    TriangleSurface surface_;
    std::vector<int> order_;
    std::vector<Eigen::Vector3d> centroids_;
    std::vector<Node> nodes_;
};

/// Per point, tree.closest_point(points[i]) (in parallel, each in its own slot: the same
/// for any number of threads).
[[nodiscard]] std::vector<ClosestPoint> closest_points(const AabbTree& tree, const std::vector<Eigen::Vector3d>& points);
/// Per point, its distance to the surface (sqrt of the squared distance), the same way.
[[nodiscard]] std::vector<double> distances(const AabbTree& tree, const std::vector<Eigen::Vector3d>& points);

}  // namespace dualhex::geometry
