#include "dualhex/topology/link.hpp"

#include <algorithm>

namespace dualhex {
namespace {

// The two edges of face f at its i-th corner, in the order walked by half-face side.
std::array<EdgeHandle, 2> corner_edges(const CellComplex& k, FaceHandle f, std::size_t i, int side) {
    const auto edges = k.face_edges(f);
    const std::size_t n = edges.size();
    const EdgeHandle in = edges[(i + n - 1) % n], out = edges[i];
    return side == 0 ? std::array{in, out} : std::array{out, in};
}

int link_vertex(const VertexLink& link, EdgeHandle e) {
    const auto it = std::find(link.vertices.begin(), link.vertices.end(), e);
    return it == link.vertices.end() ? -1 : static_cast<int>(it - link.vertices.begin());
}

// Chains the cell's (in, out) corner edges at v into one cycle, or returns empty.
std::vector<int> chain_corners(const VertexLink& link, const std::vector<std::array<EdgeHandle, 2>>& corners) {
    std::vector<int> cycle;
    std::vector<char> used(corners.size(), 0);
    std::size_t at = 0;
    for (std::size_t step = 0; step < corners.size(); ++step) {
        if (used[at]) return {};
        used[at] = 1;
        cycle.push_back(link_vertex(link, corners[at][0]));
        const EdgeHandle out = corners[at][1];
        std::size_t next = corners.size();
        for (std::size_t j = 0; j < corners.size(); ++j)
            if (corners[j][0] == out) {
                if (next != corners.size()) return {};  // two corners leave through `out`
                next = j;
            }
        if (next == corners.size()) return {};
        at = next;
    }
    return at == 0 ? cycle : std::vector<int>{};
}

}  // namespace

VertexLink vertex_link(const CellComplex& k, const Incidence& inc, VertexHandle v) {
    VertexLink link;
    link.center = v;
    const auto ve = inc.vertex_edges(v);
    link.vertices.assign(ve.begin(), ve.end());

    for (FaceHandle f : inc.vertex_faces(v)) {
        const auto loop = k.face_vertices(f);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            if (loop[i] != v) continue;
            const auto [a, b] = corner_edges(k, f, i, 0);
            link.edges.push_back({link_vertex(link, a), link_vertex(link, b)});
            link.edge_faces.push_back(f);
        }
    }

    for (CellHandle c : inc.vertex_cells(v)) {
        std::vector<std::array<EdgeHandle, 2>> corners;
        for (HalfFaceHandle h : k.cell_halffaces(c)) {
            const auto loop = k.face_vertices(h.face());
            for (std::size_t i = 0; i < loop.size(); ++i)
                if (loop[i] == v) corners.push_back(corner_edges(k, h.face(), i, h.side()));
        }
        std::vector<int> cycle = chain_corners(link, corners);
        if (cycle.empty()) {
            ++link.broken_cell_corners;
            continue;
        }
        link.faces.push_back(std::move(cycle));
        link.face_cells.push_back(c);
    }
    return link;
}

bool VertexLink::is_closed_connected_surface() const {
    if (broken_cell_corners != 0 || vertices.empty()) return false;
    // Each link edge, as an unordered pair, must be distinct and bound exactly two faces.
    // (Sorted vectors, not a map: this runs once per interior vertex.)
    std::vector<std::array<int, 2>> pairs;
    for (auto [a, b] : edges) {
        if (a < 0 || b < 0 || a == b) return false;
        pairs.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(pairs.begin(), pairs.end());
    if (std::adjacent_find(pairs.begin(), pairs.end()) != pairs.end()) return false;
    std::vector<int> uses(pairs.size(), 0);
    for (const auto& face : faces)
        for (std::size_t i = 0; i < face.size(); ++i) {
            const int a = face[i], b = face[(i + 1) % face.size()];
            const std::array<int, 2> key{std::min(a, b), std::max(a, b)};
            const auto it = std::lower_bound(pairs.begin(), pairs.end(), key);
            if (it == pairs.end() || *it != key) return false;
            ++uses[static_cast<std::size_t>(it - pairs.begin())];
        }
    if (std::any_of(uses.begin(), uses.end(), [](int n) { return n != 2; })) return false;
    // Connected through link edges.
    std::vector<int> comp(vertices.size());
    for (std::size_t i = 0; i < comp.size(); ++i) comp[i] = static_cast<int>(i);
    for (bool changed = true; changed;) {
        changed = false;
        for (auto [a, b] : edges) {
            const int m = std::min(comp[static_cast<std::size_t>(a)], comp[static_cast<std::size_t>(b)]);
            for (int x : {a, b})
                if (comp[static_cast<std::size_t>(x)] != m) comp[static_cast<std::size_t>(x)] = m, changed = true;
        }
    }
    return std::all_of(comp.begin(), comp.end(), [](int c) { return c == 0; });
}

bool VertexLink::is_octahedron() const {
    if (vertices.size() != 6 || edges.size() != 12 || faces.size() != 8) return false;
    for (const auto& f : faces)
        if (f.size() != 3) return false;
    return is_closed_connected_surface();
}

}  // namespace dualhex
