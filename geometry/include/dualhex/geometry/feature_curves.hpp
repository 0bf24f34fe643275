#pragma once
// Sharp features of a closed triangle surface: feature edges, corners and the curves
// between them.
//
// Input : a closed, edge-manifold TriangleSurface (every edge in exactly two triangles, as
//         read_surface/clean_surface guarantee) and FeatureOptions.
// Output: FeatureSet — the feature edges (input vertex ids), the corners (input vertex
//         ids), the feature curves, each a polyline of input vertices from corner to
//         corner, or closed, and the patches (triangles joined across non-feature edges).
// Errors: std::invalid_argument for an angle outside (0, 180) or an edge not used by
//         exactly two triangles (the message names the edge).
//
// An edge is a feature edge iff the angle between the normals of its two triangles
// exceeds `angle_degrees` (a crease of dihedral angle 180 - that). A triangle whose
// normal is degenerate (zero area up to rounding) makes no edge a feature: its normal is
// undefined. A vertex is a corner iff it has 1 or >= 3 feature edges, or 2 whose
// directions turn by more than `turn_degrees` there (a sharp bend along one curve).
// Curves are the chains of feature edges split at corners; a chain without corners is a
// closed curve. With `min_chain_length`, the feature edges of chains shorter than it are
// dropped first (smooth, so patches join across them). All combinatorics are by vertex id; floats only decide the two angles.
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {

struct FeatureOptions {
    /// Normal deviation above which an edge is sharp. 45 degrees: on the shared CAD models
    /// the feature counts are stable from 45 to 60, while coarse tessellations of smooth
    /// patches (gmsh_lever's cylinders) bend by up to ~40 per edge (geometry/README.md).
    double angle_degrees = 45.0;
    /// Turn of the curve direction at a 2-edge vertex above which it is a corner.
    double turn_degrees = 45.0;
    /// Chains of feature edges (connected, corners included) shorter than this in total
    /// (model units) are not features: their edges count as smooth. 0 (default): all kept.
    /// The mesher sets it from the bbox diagonal, so tessellation creases of organic models
    /// (short isolated chains) are not snapped.
    double min_chain_length = 0.0;
};

struct FeatureCurve {
    std::vector<int> vertices;             ///< input vertex ids in order (closed: first not repeated)
    std::vector<Eigen::Vector3d> points;   ///< their positions (same length)
    bool closed = false;                   ///< closed loop without a corner on it
    /// Patches on its left and right, walking along it seen from outside (outward surface).
    std::array<int, 2> sides{-1, -1};
    [[nodiscard]] double length() const;
};

struct FeatureSet {
    std::vector<std::array<int, 2>> edges;  ///< feature edges, smaller id first, sorted
    std::vector<int> corners;               ///< corner vertex ids, sorted
    std::vector<FeatureCurve> curves;
    /// (triangles): patch id, the triangles joined across non-feature edges, numbered in
    /// order of their smallest triangle; `patches` of them.
    std::vector<int> patch;
    int patches = 0;
    /// The curves as point polylines (closed ones without the repeated first point).
    [[nodiscard]] std::vector<std::vector<Eigen::Vector3d>> polylines() const;
};

[[nodiscard]] FeatureSet detect_features(const TriangleSurface& surface, const FeatureOptions& options = {});

/// The point of polyline `points` (closed: with the segment back to the start) nearest to
/// `p`, and the arc length at which it lies. Precondition: at least one point.
struct PolylinePoint {
    Eigen::Vector3d point;
    double arc = 0;
    double distance = 0;
};
[[nodiscard]] PolylinePoint closest_on_polyline(const std::vector<Eigen::Vector3d>& points, bool closed,
                                                const Eigen::Vector3d& p);

/// The point at arc length `arc` (clamped to [0, length]) along the polyline.
[[nodiscard]] Eigen::Vector3d point_at_arc(const std::vector<Eigen::Vector3d>& points, bool closed, double arc);

}  // namespace dualhex::geometry
