#pragma once
// Hand-made all-hex complexes for the topology, repair and distance tests: a uniform
// block of nx x ny x nz unit hexes (VTK order, positive orientation) and the sub-mesh of
// the selected cells (by flag or by a predicate on (i, j, k)) with its vertices renumbered.
#include <array>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"

namespace geometry_test {

struct HexBlock {
    int nx = 0, ny = 0, nz = 0;
    dualhex::geometry::HexMesh mesh;  ///< all cells, cell (i,j,k) at index cell(i,j,k)
    [[nodiscard]] int cell(int i, int j, int k) const { return i + nx * (j + ny * k); }
};

/// nx x ny x nz hexes of edge h filling [0, nx h] x [0, ny h] x [0, nz h] + origin.
inline HexBlock hex_block(int nx, int ny, int nz, double h = 1.0,
                          const Eigen::Vector3d& origin = Eigen::Vector3d::Zero()) {
    HexBlock b{nx, ny, nz, {}};
    auto id = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) b.mesh.points.push_back(origin + h * Eigen::Vector3d(i, j, k));
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                b.mesh.hexes.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                        id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
                                        id(i, j + 1, k + 1)});
    return b;
}

/// The selected hexes of `m`, with only their vertices (renumbered in first-use order).
inline dualhex::geometry::HexMesh selected_mesh(const dualhex::geometry::HexMesh& m, const std::vector<char>& keep) {
    dualhex::geometry::HexMesh out;
    std::vector<int> id(m.points.size(), -1);
    for (std::size_t h = 0; h < m.hexes.size(); ++h) {
        if (!keep[h]) continue;
        std::array<int, 8> q{};
        for (int c = 0; c < 8; ++c) {
            int& v = id[static_cast<std::size_t>(m.hexes[h][c])];
            if (v < 0) {
                v = static_cast<int>(out.points.size());
                out.points.push_back(m.points[static_cast<std::size_t>(m.hexes[h][c])]);
            }
            q[c] = v;
        }
        out.hexes.push_back(q);
    }
    return out;
}

/// The cells (i, j, k) of `b` for which keep(i, j, k) holds, as their own mesh.
template <class Keep>
dualhex::geometry::HexMesh picked_mesh(const HexBlock& b, Keep keep) {
    std::vector<char> flags(b.mesh.hexes.size(), 0);
    for (int k = 0; k < b.nz; ++k)
        for (int j = 0; j < b.ny; ++j)
            for (int i = 0; i < b.nx; ++i) flags[static_cast<std::size_t>(b.cell(i, j, k))] = keep(i, j, k) ? 1 : 0;
    return selected_mesh(b.mesh, flags);
}

}  // namespace geometry_test
