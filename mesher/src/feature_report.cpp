// The crease measurement (feature_report.hpp).
#include "dualhex/mesher/feature_report.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

#include "dualhex/geometry/quality.hpp"
#include "hex_edges.hpp"

namespace dualhex::mesher {
namespace {

using Segment = std::array<Eigen::Vector3d, 2>;

double point_segment_distance(const Eigen::Vector3d& p, const Segment& s) {
    const Eigen::Vector3d ab = s[1] - s[0];
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - s[0]).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (s[0] + t * ab)).norm();
}

// Answers "is some segment within `radius` of p?" through a uniform hash grid of cell
// 2 * radius: each segment is listed in the cells around its samples (spacing radius), so
// every segment within radius of p is listed in p's cell.
class SegmentGrid {
public:
    SegmentGrid(std::vector<Segment> segments, double radius) : segments_(std::move(segments)), radius_(radius) {
        for (std::size_t i = 0; i < segments_.size(); ++i) {
            const Segment& s = segments_[i];
            const int steps = 1 + static_cast<int>(std::ceil((s[1] - s[0]).norm() / radius_));
            std::vector<std::uint64_t> keys;
            for (int k = 0; k <= steps; ++k) {
                const Eigen::Vector3d p = s[0] + (s[1] - s[0]) * (static_cast<double>(k) / steps);
                const Eigen::Vector3i c = cell(p);
                for (int dx = -1; dx <= 1; ++dx)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dz = -1; dz <= 1; ++dz) keys.push_back(key(c + Eigen::Vector3i(dx, dy, dz)));
            }
            std::sort(keys.begin(), keys.end());
            keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
            for (auto k : keys) cells_[k].push_back(static_cast<int>(i));
        }
    }

    [[nodiscard]] bool near(const Eigen::Vector3d& p) const {
        const auto it = cells_.find(key(cell(p)));
        if (it == cells_.end()) return false;
        return std::any_of(it->second.begin(), it->second.end(), [&](int i) {
            return point_segment_distance(p, segments_[static_cast<std::size_t>(i)]) <= radius_;
        });
    }

private:
    std::vector<Segment> segments_;
    double radius_;
    std::unordered_map<std::uint64_t, std::vector<int>> cells_;

    [[nodiscard]] Eigen::Vector3i cell(const Eigen::Vector3d& p) const {
        return (p / (2 * radius_)).array().floor().cast<int>();
    }
    [[nodiscard]] static std::uint64_t key(const Eigen::Vector3i& c) {  // 21 bits per axis, wraps
        auto part = [](int x) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) & 0x1fffffu; };
        return part(c.x()) << 42 | part(c.y()) << 21 | part(c.z());
    }
};

// The hex boundary edges whose two boundary quads' normals deviate by more than `degrees`.
std::vector<Segment> crease_edges(const geometry::HexMesh& mesh, double degrees) {
    const auto quads = geometry::boundary_quads(mesh);
    std::vector<Eigen::Vector3d> normals;
    std::unordered_map<std::uint64_t, std::vector<int>> quads_at;
    for (std::size_t q = 0; q < quads.size(); ++q) {
        const auto& c = quads[q];
        auto p = [&](int i) { return mesh.points[static_cast<std::size_t>(c[static_cast<std::size_t>(i)])]; };
        normals.push_back((p(2) - p(0)).cross(p(3) - p(1)).normalized());
        for (int i = 0; i < 4; ++i)
            quads_at[detail::edge_key(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>((i + 1) % 4)])]
                .push_back(static_cast<int>(q));
    }
    const double cos_max = std::cos(degrees * std::numbers::pi / 180.0);
    std::vector<Segment> out;
    for (const auto& [key, qs] : quads_at) {
        const bool crease = qs.size() != 2 || !(normals[static_cast<std::size_t>(qs[0])].dot(
                                                    normals[static_cast<std::size_t>(qs[1])]) >= cos_max);
        if (crease)
            out.push_back({mesh.points[key >> 32], mesh.points[key & 0xffffffffu]});
    }
    return out;
}

}  // namespace

CreaseMeasure measure_creases(const geometry::HexMesh& mesh, const geometry::TriangleSurface& surface,
                              const geometry::FeatureSet& features, double angle_degrees, double tolerance) {
    if (!(tolerance > 0)) throw std::invalid_argument("crease tolerance must be > 0");
    if (!(angle_degrees > 0 && angle_degrees < 180)) throw std::invalid_argument("crease angle must be in (0, 180)");
    const double radius = tolerance * geometry::bounding_box(surface).diagonal().norm();
    if (!(radius > 0)) throw std::invalid_argument("crease measurement: surface with an empty bounding box");

    std::vector<Segment> input;
    for (const auto& e : features.edges)
        input.push_back(
            {surface.vertices[static_cast<std::size_t>(e[0])], surface.vertices[static_cast<std::size_t>(e[1])]});
    std::vector<Segment> creases = crease_edges(mesh, angle_degrees / 2);

    CreaseMeasure m;
    m.crease_edges = creases.size();
    const SegmentGrid to_input(input, radius);
    for (const auto& s : creases) m.spurious_creases += to_input.near(0.5 * (s[0] + s[1])) ? 0 : 1;
    const SegmentGrid to_creases(std::move(creases), radius);
    for (const auto& s : input) {
        const int steps = 1 + static_cast<int>(std::ceil((s[1] - s[0]).norm() / (radius / 2)));
        for (int k = 0; k <= steps; ++k) {
            ++m.samples;
            m.samples_kept += to_creases.near(s[0] + (s[1] - s[0]) * (static_cast<double>(k) / steps)) ? 1 : 0;
        }
    }
    return m;
}

}  // namespace dualhex::mesher
