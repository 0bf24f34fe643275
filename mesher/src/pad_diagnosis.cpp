// Why hexes are bad (pad_diagnosis.hpp): causes counted per pad hex below a threshold.
#include "dualhex/mesher/pad_diagnosis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>

#include <sstream>

#include <Eigen/Geometry>

#include "dualhex/geometry/hex_topology.hpp"

namespace dualhex::mesher {
namespace {

using Quad = std::array<int, 4>;

Quad base_of(const geometry::HexMesh& mesh, std::size_t h) {
    const auto& x = mesh.hexes[h];
    return {x[0], x[1], x[2], x[3]};
}

Eigen::Vector3d quad_normal(const geometry::HexMesh& mesh, const Quad& q) {
    const auto& p = mesh.points;
    const auto at = [&](int i) { return p[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])]; };
    return (at(2) - at(0)).cross(at(3) - at(1)).normalized();
}

Eigen::Vector3d quad_centre(const geometry::HexMesh& mesh, const Quad& q) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : q) c += mesh.points[static_cast<std::size_t>(v)];
    return c / 4.0;
}

// The pad hexes' base quads around each base edge and at each base vertex.
struct BaseAdjacency {
    std::map<std::pair<int, int>, std::vector<std::size_t>> at_edge;
    std::map<int, int> quads_at_vertex;
    std::size_t first_pad = 0;
    std::vector<int> base_faces;  ///< (pad hexes, from first_pad): boundary faces of the core hex under it
};

// Per pad hex: how many boundary faces the core hex whose face is its base has (the pad
// hexes on that core hex: base quads are core boundary faces, found by sorted ids).
std::vector<int> base_core_faces(const geometry::HexMesh& mesh, std::size_t core_hexes) {
    std::map<Quad, std::size_t> owner;  // core face -> core hex
    for (std::size_t h = 0; h < core_hexes; ++h)
        for (const auto& f : geometry::kHexFaces) {
            Quad k{mesh.hexes[h][static_cast<std::size_t>(f[0])], mesh.hexes[h][static_cast<std::size_t>(f[1])],
                   mesh.hexes[h][static_cast<std::size_t>(f[2])], mesh.hexes[h][static_cast<std::size_t>(f[3])]};
            std::sort(k.begin(), k.end());
            owner.emplace(k, h);
        }
    std::vector<std::size_t> base_hex;
    std::map<std::size_t, int> faces_of;
    for (std::size_t h = core_hexes; h < mesh.hexes.size(); ++h) {
        Quad k = base_of(mesh, h);
        std::sort(k.begin(), k.end());
        const auto it = owner.find(k);
        base_hex.push_back(it == owner.end() ? SIZE_MAX : it->second);
        ++faces_of[base_hex.back()];
    }
    std::vector<int> out;
    for (std::size_t c : base_hex) out.push_back(c == SIZE_MAX ? 0 : faces_of[c]);
    return out;
}

BaseAdjacency base_adjacency(const geometry::HexMesh& mesh, std::size_t core_hexes) {
    BaseAdjacency a;
    for (std::size_t h = core_hexes; h < mesh.hexes.size(); ++h) {
        const Quad q = base_of(mesh, h);
        for (std::size_t i = 0; i < 4; ++i) {
            a.at_edge[std::minmax(q[i], q[(i + 1) % 4])].push_back(h);
            ++a.quads_at_vertex[q[i]];
        }
    }
    a.first_pad = core_hexes;
    a.base_faces = base_core_faces(mesh, core_hexes);
    return a;
}

double mean_base_edge(const geometry::HexMesh& mesh, const Quad& q) {
    double sum = 0;
    for (std::size_t i = 0; i < 4; ++i)
        sum += (mesh.points[static_cast<std::size_t>(q[i])] - mesh.points[static_cast<std::size_t>(q[(i + 1) % 4])]).norm();
    return sum / 4;
}

// Adds the causes pad hex h shows to d; true if it shows any.
bool count_causes(const geometry::HexMesh& mesh, std::size_t h, const BaseAdjacency& adj,
                  const VertexConstraints& constraints, PadDiagnosis& d) {
    const auto& x = mesh.hexes[h];
    const Quad q = base_of(mesh, h);
    const Eigen::Vector3d n = quad_normal(mesh, q);
    const double edge = mean_base_edge(mesh, q);
    bool convex = false, concave = false, irregular = false, collapsed = false, feature = false;
    for (std::size_t i = 0; i < 4; ++i) {
        const auto key = std::minmax(q[i], q[(i + 1) % 4]);
        for (std::size_t g : adj.at_edge.at(key)) {
            if (g == h) continue;
            const Quad r = base_of(mesh, g);
            if (quad_normal(mesh, r).dot(n) > std::cos(M_PI / 4)) continue;  // no fold here
            const Eigen::Vector3d mid =
                0.5 * (mesh.points[static_cast<std::size_t>(key.first)] + mesh.points[static_cast<std::size_t>(key.second)]);
            ((quad_centre(mesh, r) - mid).dot(n) < 0 ? convex : concave) = true;
        }
        irregular = irregular || adj.quads_at_vertex.at(q[i]) != 4;
        const Eigen::Vector3d top_edge =
            mesh.points[static_cast<std::size_t>(x[4 + i])] - mesh.points[static_cast<std::size_t>(x[4 + (i + 1) % 4])];
        collapsed = collapsed || top_edge.norm() < 0.25 * edge;
    }
    double height = 0;
    for (std::size_t i = 0; i < 4; ++i)
        height += (mesh.points[static_cast<std::size_t>(x[4 + i])] - mesh.points[static_cast<std::size_t>(x[i])]).norm() / 4;
    for (int v : x) {
        const VertexRole role = constraints.role[static_cast<std::size_t>(v)];
        feature = feature || role == VertexRole::Curve || role == VertexRole::Corner;
    }
    const bool thin = height < 0.25 * edge;
    const bool exposed = adj.base_faces[h - adj.first_pad] >= 3;
    d.exposed_base += exposed;
    d.convex_edge += convex;
    d.concave_edge += concave;
    d.irregular_vertex += irregular;
    d.collapsed_top += collapsed;
    d.thin += thin;
    d.feature += feature;
    return convex || concave || irregular || collapsed || thin || feature || exposed;
}

}  // namespace

PadDiagnosis diagnose_pad(const geometry::HexMesh& mesh, std::size_t core_hexes, const VertexConstraints& constraints,
                          const std::vector<double>& sj, double threshold) {
    PadDiagnosis d;
    d.threshold = threshold;
    const BaseAdjacency adj = base_adjacency(mesh, core_hexes);
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        if (sj[h] >= threshold) continue;  // NaN falls through: below
        const bool flat = !(sj[h] > 1e-6);
        if (h < core_hexes) {
            ++d.core_below;
            d.core_inverted += flat;
            continue;
        }
        ++d.pad_below;
        d.pad_inverted += flat;
        if (!count_causes(mesh, h, adj, constraints, d)) ++d.none;
    }
    return d;
}

std::string PadDiagnosis::summary() const {
    std::ostringstream s;
    s << "below " << threshold << ": core " << core_below << " (" << core_inverted << " inverted), pad " << pad_below
      << " (" << pad_inverted << " inverted); pad causes: convex " << convex_edge << ", concave " << concave_edge
      << ", corner-vertex " << irregular_vertex << ", collapsed-top " << collapsed_top << ", thin " << thin
      << ", feature " << feature << ", exposed-base " << exposed_base << ", none " << none;
    return s.str();
}

}  // namespace dualhex::mesher
