// The extract stage (extract.hpp).
#include "dualhex/mesher/extract.hpp"

#include <array>
#include <vector>

#include "dualhex/geometry/inside.hpp"

namespace dualhex::mesher {

geometry::HexMesh extract_inside(const ClippedDual& dual, std::int64_t extent, const geometry::RootCube& root,
                                 const geometry::AabbTree& tree) {
    const double ext = static_cast<double>(extent);
    std::vector<Eigen::Vector3d> all_points;
    all_points.reserve(dual.points.size());
    for (const RationalPoint& p : dual.points)
        all_points.push_back(root.origin +
                             root.size * Eigen::Vector3d(p.coordinate(0, ext), p.coordinate(1, ext), p.coordinate(2, ext)));
    std::vector<int> new_id(all_points.size(), -1);
    geometry::HexMesh mesh;
    for (const auto& h : dual.hexes) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (std::uint32_t v : h) c += all_points[v];
        c /= 8.0;
        if (!geometry::is_inside(tree, c)) continue;
        std::array<int, 8> q{};
        for (std::size_t i = 0; i < 8; ++i) {
            int& id = new_id[h[i]];
            if (id < 0) {
                id = static_cast<int>(mesh.points.size());
                mesh.points.push_back(all_points[h[i]]);
            }
            q[i] = id;
        }
        mesh.hexes.push_back(q);
    }
    return mesh;
}

}  // namespace dualhex::mesher
