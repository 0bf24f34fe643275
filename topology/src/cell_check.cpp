// Check (1): faces are simple polygons; each cell bounds an oriented topological sphere.
#include <algorithm>
#include <numeric>
#include <string>

#include "checks.hpp"

namespace dualhex::detail {
namespace {

// One traversal of an edge by one of the cell's half-faces.
struct DirectedEdge {
    EdgeHandle edge;
    bool forward;          // walked from the smaller to the larger vertex id
    std::uint32_t local;   // index of the half-face within the cell
};

// A corner of a half-face at `v`, walked prev -> v -> next in the half-face's orientation.
struct Corner {
    VertexHandle v, prev, next;
};

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

void add_cell_violation(ValidationReport& r, ViolationKind kind, CellHandle c, std::string msg,
                        EdgeHandle e = {}, VertexHandle v = {}) {
    Violation viol{kind, v, e, {}, c, std::move(msg)};
    r.add(std::move(viol));
}

// Walks the corners at one vertex: following next -> prev must visit all of them in one
// cycle, otherwise the cell's surface is pinched (or torn) at that vertex.
bool corners_form_one_cycle(std::span<const Corner> corners) {
    const std::size_t n = corners.size();
    for (std::size_t i = 1; i < n; ++i)
        if (corners[i].prev == corners[i - 1].prev) return false;  // two corners leave the same edge
    auto by_prev = [&](VertexHandle p) -> std::size_t {
        const auto it = std::lower_bound(corners.begin(), corners.end(), p,
                                         [](const Corner& c, VertexHandle q) { return c.prev < q; });
        return it != corners.end() && it->prev == p ? static_cast<std::size_t>(it - corners.begin()) : n;
    };
    std::size_t at = 0, steps = 0;
    do {
        at = by_prev(corners[at].next);
        if (at == n) return false;
        ++steps;
    } while (at != 0 && steps <= n);
    return steps == n;
}

// The cell's surface flattened: directed edges, corners, vertices of all its half-faces.
struct CellSurface {
    std::vector<DirectedEdge> dedges;
    std::vector<Corner> corners;
    std::vector<VertexHandle> verts;
};

CellSurface gather_surface(const CellComplex& k, std::span<const HalfFaceHandle> hfs) {
    CellSurface s;
    for (std::uint32_t local = 0; local < hfs.size(); ++local) {
        const HalfFaceHandle h = hfs[local];
        const auto loop = k.face_vertices(h.face());
        const auto edges = k.face_edges(h.face());
        const std::size_t n = loop.size();
        for (std::size_t i = 0; i < n; ++i) {
            const VertexHandle a = loop[i], b = loop[(i + 1) % n], before = loop[(i + n - 1) % n];
            s.verts.push_back(a);
            if (a != b) s.dedges.push_back({edges[i], (a < b) != (h.side() == 1), local});
            s.corners.push_back(h.side() == 0 ? Corner{a, before, b} : Corner{a, b, before});
        }
    }
    return s;
}

// Each edge used exactly twice, in opposite directions. Returns the number of distinct
// edges and, through `components`, the number of face components (faces joined along
// shared edges).
std::size_t check_cell_edges(CellHandle c, std::vector<DirectedEdge>& dedges, std::size_t n_faces,
                             std::size_t& components, ValidationReport& report) {
    std::sort(dedges.begin(), dedges.end(), [](const DirectedEdge& x, const DirectedEdge& y) { return x.edge < y.edge; });
    std::vector<std::uint32_t> parent(n_faces);
    std::iota(parent.begin(), parent.end(), 0u);
    std::size_t n_edges = 0;
    for (std::size_t i = 0, j = 0; i < dedges.size(); i = j) {
        while (j < dedges.size() && dedges[j].edge == dedges[i].edge) ++j;
        ++n_edges;
        const EdgeHandle e = dedges[i].edge;
        for (std::size_t t = i + 1; t < j; ++t)
            parent[find_root(parent, dedges[t].local)] = find_root(parent, dedges[i].local);
        if (j - i == 1)
            add_cell_violation(report, ViolationKind::CellOpenEdge, c, "edge used by one face of the cell only", e);
        else if (j - i > 2)
            add_cell_violation(report, ViolationKind::CellNonManifoldEdge, c,
                               "edge used " + std::to_string(j - i) + " times in the cell", e);
        else if (dedges[i].forward == dedges[i + 1].forward)
            add_cell_violation(report, ViolationKind::CellInconsistentOrientation, c,
                               "edge walked twice in the same direction", e);
    }
    components = 0;
    for (std::uint32_t i = 0; i < parent.size(); ++i) components += find_root(parent, i) == i;
    return n_edges;
}

// Around each vertex, the cell's face corners form a single cycle.
void check_cell_vertices(CellHandle c, std::vector<Corner>& corners, ValidationReport& report) {
    std::sort(corners.begin(), corners.end(), [](const Corner& x, const Corner& y) {
        return x.v != y.v ? x.v < y.v : x.prev < y.prev;
    });
    for (std::size_t i = 0, j = 0; i < corners.size(); i = j) {
        while (j < corners.size() && corners[j].v == corners[i].v) ++j;
        if (!corners_form_one_cycle(std::span<const Corner>(corners.data() + i, j - i)))
            add_cell_violation(report, ViolationKind::CellNonManifoldVertex, c,
                               "the cell's faces around this vertex are not a single cycle", {}, corners[i].v);
    }
}

}  // namespace

void check_face(const CellComplex& k, FaceHandle f, ValidationReport& report) {
    const auto loop = k.face_vertices(f);
    std::vector<VertexHandle> sorted(loop.begin(), loop.end());
    std::sort(sorted.begin(), sorted.end());
    const auto distinct = static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    if (distinct < 3)
        report.add({ViolationKind::FaceTooFewVertices, {}, {}, f, {},
                    "face has " + std::to_string(distinct) + " distinct vertices"});
    if (distinct < loop.size())
        report.add({ViolationKind::FaceRepeatedVertex, {}, {}, f, {},
                    "loop of " + std::to_string(loop.size()) + " repeats a vertex: not a simple polygon"});
}

void check_cell(const CellComplex& k, CellHandle c, ValidationReport& report) {
    const auto hfs = k.cell_halffaces(c);
    std::vector<FaceHandle> faces;
    for (HalfFaceHandle h : hfs) faces.push_back(h.face());
    std::sort(faces.begin(), faces.end());
    for (std::size_t i = 1; i < faces.size(); ++i)
        if (faces[i] == faces[i - 1])
            report.add({ViolationKind::CellRepeatedFace, {}, {}, faces[i], c, "face listed twice in the cell"});

    CellSurface surface = gather_surface(k, hfs);
    std::size_t components = 0;
    const std::size_t n_edges = check_cell_edges(c, surface.dedges, hfs.size(), components, report);
    if (components > 1)
        add_cell_violation(report, ViolationKind::CellDisconnected, c,
                           "faces form " + std::to_string(components) + " connected components");

    std::sort(surface.verts.begin(), surface.verts.end());
    const auto n_verts = std::unique(surface.verts.begin(), surface.verts.end()) - surface.verts.begin();
    const std::int64_t chi = n_verts - static_cast<std::int64_t>(n_edges) + static_cast<std::int64_t>(hfs.size());
    if (chi != 2)
        add_cell_violation(report, ViolationKind::CellNotSphere, c, "V - E + F = " + std::to_string(chi) + " (expected 2)");

    check_cell_vertices(c, surface.corners, report);
}

}  // namespace dualhex::detail
