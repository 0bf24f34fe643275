// The report stage's figures (mesh_report.hpp).
#include "dualhex/mesher/mesh_report.hpp"

#include <unordered_map>

#include "dualhex/geometry/quality.hpp"
#include "hex_edges.hpp"

namespace dualhex::mesher {

std::map<int, std::size_t> interior_singular_edge_valences(const geometry::HexMesh& mesh) {
    std::unordered_map<std::uint64_t, int> hexes_at;
    hexes_at.reserve(mesh.hexes.size() * 4);
    for (const auto& h : mesh.hexes)
        for (const auto& e : detail::kHexEdges) ++hexes_at[detail::edge_key(h[e[0]], h[e[1]])];
    std::unordered_map<std::uint64_t, char> boundary;
    for (const auto& q : geometry::boundary_quads(mesh))
        for (int i = 0; i < 4; ++i) boundary[detail::edge_key(q[i], q[(i + 1) % 4])] = 1;
    std::map<int, std::size_t> out;
    for (const auto& [key, n] : hexes_at)
        if (n != 4 && !boundary.contains(key)) ++out[n];
    return out;
}

}  // namespace dualhex::mesher
