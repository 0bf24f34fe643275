// Check (4) on the dual itself: is the dual cell of a vertex a combinatorial cube?
#include <algorithm>
#include <utility>
#include <vector>

#include "dualhex/topology/dual.hpp"

namespace dualhex {
namespace {

std::string str(std::size_t n) { return std::to_string(n); }

// Small sets as sorted vectors: these run once per interior vertex, so no node allocation.
bool all_distinct(std::vector<std::pair<CellHandle, CellHandle>>& pairs) {
    std::sort(pairs.begin(), pairs.end());
    return std::adjacent_find(pairs.begin(), pairs.end()) == pairs.end();
}

// Cells around edge e (all faces containing e contain its endpoints): one cycle of length 4.
std::optional<std::string> dual_face_defect(const Incidence& inc, EdgeHandle e) {
    const auto cells = inc.edge_cells(e);
    const auto faces = inc.edge_faces(e);
    if (cells.size() != 4 || faces.size() != 4)
        return "dual face of edge " + std::to_string(e.idx) + " has " + str(cells.size()) + " vertices and " +
               str(faces.size()) + " sides";
    std::vector<int> degree(4, 0);
    std::vector<std::pair<CellHandle, CellHandle>> sides;
    for (FaceHandle f : faces) {
        const auto fc = inc.face_cells(f);
        if (fc.size() != 2 || fc[0] == fc[1]) return "dual face of edge " + std::to_string(e.idx) + " has a broken side";
        for (CellHandle c : fc) ++degree[static_cast<std::size_t>(std::find(cells.begin(), cells.end(), c) - cells.begin())];
        sides.push_back(std::minmax(fc[0], fc[1]));
    }
    if (!all_distinct(sides) || std::any_of(degree.begin(), degree.end(), [](int d) { return d != 2; }))
        return "dual face of edge " + std::to_string(e.idx) + " is not a 4-cycle";
    // 4 vertices, 4 distinct sides, all of degree 2: a 4-cycle or two 2-cycles; the
    // latter would need repeated sides, excluded above.
    return std::nullopt;
}

}  // namespace

std::optional<std::string> dual_cube_defect(const CellComplex& k, const Incidence& inc, VertexHandle v) {
    const auto cells = inc.vertex_cells(v);
    const auto faces = inc.vertex_faces(v);
    const auto edges = inc.vertex_edges(v);
    if (cells.size() != 8 || faces.size() != 12 || edges.size() != 6)
        return "dual cell has " + str(cells.size()) + " vertices, " + str(faces.size()) + " edges, " +
               str(edges.size()) + " faces (cube: 8, 12, 6)";

    // Dual edges: each face joins two distinct cells, no pair twice; degrees 3.
    std::vector<std::pair<CellHandle, CellHandle>> dual_edges;
    std::vector<int> degree(cells.size(), 0);
    auto slot = [&](CellHandle c) { return static_cast<std::size_t>(std::find(cells.begin(), cells.end(), c) - cells.begin()); };
    for (FaceHandle f : faces) {
        const auto fc = inc.face_cells(f);
        if (fc.size() != 2 || fc[0] == fc[1]) return "dual edge of face " + std::to_string(f.idx) + " is not a proper edge";
        dual_edges.push_back(std::minmax(fc[0], fc[1]));
        ++degree[slot(fc[0])];
        ++degree[slot(fc[1])];
        // The dual edge lies in the dual faces of f's edges at v: exactly two.
        int at_v = 0;
        for (EdgeHandle e : k.face_edges(f)) {
            const auto [a, b] = k.edge_vertices(e);
            at_v += (a == v) + (b == v);
        }
        if (at_v != 2) return "dual edge of face " + std::to_string(f.idx) + " lies in " + std::to_string(at_v) + " dual faces";
    }
    if (!all_distinct(dual_edges)) return "two dual edges join the same dual vertices";
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (degree[i] != 3) return "dual vertex (cell " + std::to_string(cells[i].idx) + ") has degree " + std::to_string(degree[i]);

    for (EdgeHandle e : edges)
        if (auto defect = dual_face_defect(inc, e)) return defect;

    // Connected: label propagation over the 12 dual edges.
    std::vector<std::size_t> label(cells.size());
    for (std::size_t i = 0; i < label.size(); ++i) label[i] = i;
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [a, b] : dual_edges) {
            std::size_t& la = label[slot(a)];
            std::size_t& lb = label[slot(b)];
            if (la != lb) la = lb = std::min(la, lb), changed = true;
        }
    }
    if (std::any_of(label.begin(), label.end(), [](std::size_t l) { return l != 0; })) return "dual cell is disconnected";
    return std::nullopt;  // connected, 8-12+6 = 2, quads, 3-regular: the cube
}

}  // namespace dualhex
