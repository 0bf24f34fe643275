// Ordering a cube-shaped dual cell as a VTK hexahedron, purely combinatorially.
//
// Around a primal edge e = (v, w), cells are ordered by the right-hand rule about v -> w.
// With outward-oriented cells, a cell c's face at e whose half-face walks e as v -> w is
// the one it leaves through turning counter-clockwise about v -> w. The dual face of e is
// the cube face on w's side, whose outward normal is v -> w; VTK's bottom quad has its
// right-hand normal pointing into the hex, so we walk the cells around e clockwise
// (leaving through the half-face walking w -> v) to get hex[0..3].
#include "dualhex/topology/dual.hpp"

#include <algorithm>

namespace dualhex {
namespace {

// Does half-face h walk the directed edge a -> b?
bool walks(const CellComplex& k, HalfFaceHandle h, VertexHandle a, VertexHandle b) {
    const auto loop = k.face_vertices(h.face());
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
        const VertexHandle p = loop[i], q = loop[(i + 1) % n];
        if (h.side() == 0 ? (p == a && q == b) : (p == b && q == a)) return true;
    }
    return false;
}

bool has_edge(const CellComplex& k, FaceHandle f, EdgeHandle e) {
    const auto edges = k.face_edges(f);
    return std::find(edges.begin(), edges.end(), e) != edges.end();
}

// The cell after c, clockwise about v -> w (the dual cell is known to be a cube).
CellHandle clockwise_next(const CellComplex& k, const Incidence& inc, EdgeHandle e, CellHandle c, VertexHandle v,
                          VertexHandle w) {
    for (FaceHandle f : inc.edge_faces(e)) {
        const auto cells = inc.face_cells(f);
        const auto hfs = inc.face_halffaces(f);
        for (std::size_t i = 0; i < cells.size(); ++i)
            if (cells[i] == c && walks(k, hfs[i], w, v)) return inc.other_cell(f, c);
    }
    return {};
}

// dual_hex without the cube check (the caller has done it).
std::optional<std::array<CellHandle, 8>> order_cube(const CellComplex& k, const Incidence& inc, VertexHandle v) {
    const EdgeHandle bottom = inc.vertex_edges(v)[0];
    const auto [a, b] = k.edge_vertices(bottom);
    const VertexHandle w = a == v ? b : a;

    std::array<CellHandle, 8> hex;
    hex[0] = inc.edge_cells(bottom)[0];
    for (int i = 1; i < 4; ++i) hex[i] = clockwise_next(k, inc, bottom, hex[i - 1], v, w);
    if (clockwise_next(k, inc, bottom, hex[3], v, w) != hex[0]) return std::nullopt;  // inconsistent orientation
    for (int i = 0; i < 4; ++i) {
        // The third dual edge at hex[i]: its face at v not containing the bottom edge.
        for (FaceHandle f : inc.vertex_faces(v))
            if (!has_edge(k, f, bottom) && std::ranges::count(inc.face_cells(f), hex[i]) == 1)
                hex[i + 4] = inc.other_cell(f, hex[i]);
        if (!hex[i + 4].valid()) return std::nullopt;
    }
    return hex;
}

}  // namespace

std::optional<std::array<CellHandle, 8>> dual_hex(const CellComplex& k, const Incidence& inc, VertexHandle v) {
    if (dual_cube_defect(k, inc, v)) return std::nullopt;
    return order_cube(k, inc, v);
}

DualResult interior_dual(const CellComplex& k, const Incidence& inc) {
    DualResult result;
    for (std::size_t i = 0; i < k.n_vertices(); ++i) {
        const VertexHandle v(i);
        if (inc.is_boundary(v)) continue;
        if (auto defect = dual_cube_defect(k, inc, v)) {
            result.errors.push_back({v, *defect});
        } else if (auto hex = order_cube(k, inc, v)) {
            result.mesh.hexes.push_back(*hex);
            result.mesh.primal_vertex.push_back(v);
        } else {
            result.errors.push_back({v, "dual cube cannot be oriented consistently"});
        }
    }
    return result;
}

DualResult interior_dual(const CellComplex& k) { return interior_dual(k, Incidence(k)); }

DualCounts count_dual(const CellComplex& k) {
    const Incidence inc(k);
    DualCounts counts;
    for (std::size_t i = 0; i < k.n_vertices(); ++i) {
        const VertexHandle v(i);
        if (inc.is_boundary(v)) continue;
        ++counts.interior_vertices;
        if (dual_cube_defect(k, inc, v)) ++counts.non_cubes;
        else ++counts.hexes;
    }
    return counts;
}

}  // namespace dualhex
