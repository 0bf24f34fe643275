// Far samples between two surfaces (far_samples.hpp).
#include "far_samples.hpp"

#include <algorithm>
#include <cmath>

namespace dualhex::mesher::detail {

std::vector<Eigen::Vector3d> surface_samples(const geometry::TriangleSurface& surface) {
    std::vector<char> used(surface.vertices.size(), 0);
    for (const auto& t : surface.triangles)
        for (int v : t) used[static_cast<std::size_t>(v)] = 1;
    std::vector<Eigen::Vector3d> out;
    for (std::size_t v = 0; v < surface.vertices.size(); ++v)
        if (used[v]) out.push_back(surface.vertices[v]);
    for (const auto& t : surface.triangles)
        out.push_back((surface.vertices[static_cast<std::size_t>(t[0])] + surface.vertices[static_cast<std::size_t>(t[1])] +
                       surface.vertices[static_cast<std::size_t>(t[2])]) / 3.0);
    return out;
}

std::vector<FarSample> far_samples(const geometry::TriangleSurface& from, const geometry::AabbTree& to, double far) {
    const std::vector<Eigen::Vector3d> samples = surface_samples(from);
    const std::vector<geometry::ClosestPoint> closest = geometry::closest_points(to, samples);  // in parallel
    std::vector<FarSample> out;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const geometry::ClosestPoint& c = closest[i];
        if (c.squared_distance > far * far) out.push_back({std::sqrt(c.squared_distance), samples[i], c.point});
    }
    std::stable_sort(out.begin(), out.end(), [](const FarSample& a, const FarSample& b) { return a.distance > b.distance; });
    return out;
}

}  // namespace dualhex::mesher::detail
