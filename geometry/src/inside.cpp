#include "dualhex/geometry/inside.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "dualhex/geometry/triangle_geometry.hpp"

namespace dualhex::geometry {

namespace {
const std::array<Eigen::Vector3d, 5>& directions() {
    static const std::array<Eigen::Vector3d, 5> dirs = [] {
        std::array<Eigen::Vector3d, 5> d = {
            Eigen::Vector3d(0.5773502691896258, 0.6180339887498949, 0.5345224838248488),
            Eigen::Vector3d(-0.7071067811865476, 0.3090169943749474, 0.6366197723675814),
            Eigen::Vector3d(0.2718281828459045, -0.8660254037844386, 0.4142135623730950),
            Eigen::Vector3d(-0.3183098861837907, -0.4472135954999579, -0.8414709848078965),
            Eigen::Vector3d(0.9092974268256817, 0.1411200080598672, -0.3826834323650898),
        };
        for (auto& v : d) v.normalize();
        return d;
    }();
    return dirs;
}
}  // namespace

int inside_votes(const AabbTree& tree, const Eigen::Vector3d& p) {
    int votes = 0;
    for (const auto& d : directions()) votes += static_cast<int>(tree.all_hits(p, d).size() % 2);
    return votes;
}

bool is_inside(const AabbTree& tree, const Eigen::Vector3d& p) {
    if (!tree.bounds().contains(p)) return false;
    return inside_votes(tree, p) >= 3;
}

double winding_number(const TriangleSurface& s, const Eigen::Vector3d& p) {
    double sum = 0;
    for (const auto& t : s.triangles) sum += solid_angle(p, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]);
    return sum / (4.0 * std::numbers::pi);
}

}  // namespace dualhex::geometry
