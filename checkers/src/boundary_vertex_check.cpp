// The boundary conditions at root-boundary vertices (compositional_boundary.hpp,
// check_boundary_vertices; proofs/README.md "Root boundary", B1-B5). Everything is exact:
// lattice positions, combinatorial links, the clipped dual with rational corners.
#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <numeric>
#include <sstream>

#include "dualhex/checkers/compositional_boundary.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/link.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {
namespace {

__extension__ typedef __int128 Int;  // 6 * volume * L^3 with L the corners' common denominator

Int det(const std::array<Int, 3>& a, const std::array<Int, 3>& b, const std::array<Int, 3>& c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The root planes (bit a) through a point.
unsigned root_planes(const LatticePoint& p, const RootSides& sides) {
    unsigned m = 0;
    for (int a = 0; a < 3; ++a)
        if (sides[static_cast<std::size_t>(a)] != 0 && p[a] == 0) m |= 1U << a;
    return m;
}

int bits(unsigned m) { return static_cast<int>((m & 1U) + ((m >> 1) & 1U) + ((m >> 2) & 1U)); }

// B2: the link of v is the k-th part of an octahedron: 6 - k link vertices, 2^(3-k)
// triangles, a disk (every link edge in one or two triangles, V - E + F = 1, connected)
// whose rim has 4, 4, 3 link edges for k = 1, 2, 3.
const char* link_defect(const VertexLink& link, int k) {
    if (link.broken_cell_corners != 0) return "a cell corner at the vertex is not one cycle";
    if (static_cast<int>(link.vertices.size()) != 6 - k) return "wrong number of edges at the vertex";
    if (static_cast<int>(link.faces.size()) != (8 >> k)) return "wrong number of cells at the vertex";
    std::map<std::pair<int, int>, int> uses;
    for (const auto& f : link.faces) {
        if (f.size() != 3) return "a cell corner at the vertex is not trihedral";
        for (std::size_t i = 0; i < 3; ++i) {
            const int a = f[i], b = f[(i + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    if (uses.size() != link.edges.size()) return "link edges and cell corners disagree";
    int rim = 0;
    for (const auto& [edge, n] : uses) {
        if (n > 2) return "a face at the vertex in more than two of its cells' corners";
        rim += n == 1 ? 1 : 0;
    }
    const long euler = static_cast<long>(link.vertices.size()) - static_cast<long>(uses.size()) + static_cast<long>(link.faces.size());
    if (euler != 1) return "the link is not a disk (V - E + F != 1)";
    if (rim != (k == 3 ? 3 : 4)) return "the link's rim has the wrong length";
    std::vector<int> seen(link.faces.size(), 0);  // connected through shared link edges
    std::vector<std::size_t> stack{0};
    seen[0] = 1;
    while (!stack.empty()) {
        const auto& f = link.faces[stack.back()];
        stack.pop_back();
        for (std::size_t g = 0; g < link.faces.size(); ++g) {
            if (seen[g]) continue;
            int shared = 0;
            for (int x : f)
                for (int y : link.faces[g]) shared += x == y ? 1 : 0;
            if (shared >= 2) seen[g] = 1, stack.push_back(g);
        }
    }
    for (int s : seen)
        if (!s) return "the link is disconnected";
    return nullptr;
}

// B3, B4: edges at v have 4, 2, 1 cells on 0, 1, 2 root planes; a face at v with one cell
// lies on a root plane.
const char* star_defect(const CellComplex& cx, const Incidence& inc, VertexHandle v, const RootSides& sides) {
    for (EdgeHandle e : inc.vertex_edges(v)) {
        const auto [a, b] = cx.edge_vertices(e);
        const int planes = bits(root_planes(cx.position(a), sides) & root_planes(cx.position(b), sides));
        if (planes == 0 && inc.is_boundary(e)) return "an edge off the root boundary is on the complex's boundary";
        if (static_cast<int>(inc.edge_cells(e).size()) != (4 >> planes)) return "an edge with the wrong number of cells";
    }
    for (FaceHandle f : inc.vertex_faces(v)) {
        if (!inc.is_boundary(f)) continue;
        unsigned common = 7;
        for (VertexHandle w : cx.face_vertices(f)) common &= root_planes(cx.position(w), sides);
        if (common == 0) return "a boundary face off the root faces";
    }
    return nullptr;
}

// B5: the clipped dual cell is a hexahedron whose corners are 2^(3-k) cells, the boundary
// faces, crease edges and corner at v (counts 4/4/0/0, 2/4/2/0, 1/3/3/1), whose faces
// made only of surface corners are k caps, each in a root plane, and positively oriented.
const char* dual_defect(const ClippedDual& dual, std::size_t h, int k, const RootSides& sides) {
    const auto& hex = dual.hexes[h];
    std::array<int, 4> kinds{};
    std::array<RationalCorner, 8> corners;
    for (std::size_t i = 0; i < 8; ++i) {
        ++kinds[static_cast<std::size_t>(dual.kind[hex[i]])];
        const RationalPoint& p = dual.points[hex[i]];
        corners[i] = {{p.sum[0], p.sum[1], p.sum[2]}, p.denominator};
    }
    static constexpr std::array<std::array<int, 4>, 3> kExpected{{{4, 4, 0, 0}, {2, 4, 2, 0}, {1, 3, 3, 1}}};
    if (kinds != kExpected[static_cast<std::size_t>(k - 1)]) return "the clipped dual cell has the wrong corners";
    static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    int caps = 0;
    for (const auto& f : kFaces) {
        bool surface = true;
        unsigned common = 7;
        for (int i : f) {
            const auto id = hex[static_cast<std::size_t>(i)];
            surface = surface && dual.kind[id] != DualVertexKind::Cell;
            unsigned m = 0;
            for (int a = 0; a < 3; ++a)
                if (sides[static_cast<std::size_t>(a)] != 0 && dual.points[id].sum[a] == 0) m |= 1U << a;
            common &= m;
        }
        if (!surface) continue;
        ++caps;
        if (common == 0) return "a boundary face of the clipped dual cell is off the root faces";
    }
    if (caps != k) return "the clipped dual cell has the wrong number of faces on the root boundary";
    if (!hex_positively_oriented(corners)) return "the clipped dual cell is not positively oriented";
    return nullptr;
}

}  // namespace

// On a root plane and strictly inside the box otherwise: the vertex's star is all in it.
bool on_checked_planes(const LatticePoint& p, std::int64_t half, const RootSides& sides) {
    bool on_root = false, inside = true;
    for (int a = 0; a < 3; ++a) {
        const int s = sides[static_cast<std::size_t>(a)];
        if (s != 0 && p[a] == 0) on_root = true;
        else inside = inside && (s > 0 ? 0 : -half) < p[a] && p[a] < (s < 0 ? 0 : half);
    }
    return on_root && inside;
}

bool hex_positively_oriented(const std::array<RationalCorner, 8>& corners) {
    std::int64_t l = 1;
    for (const auto& c : corners) l = std::lcm(l, c.denominator);
    std::array<std::array<Int, 3>, 8> p{};
    for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t a = 0; a < 3; ++a)  // relative to corner 0 keeps the products small
            p[i][a] = Int(corners[i].sum[a]) * (l / corners[i].denominator) -
                      Int(corners[0].sum[a]) * (l / corners[0].denominator);
    // Outward faces of a VTK hexahedron, each quad as two triangles from its first corner.
    static constexpr int kFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    Int six_volume = 0;
    for (const auto& f : kFaces) {
        six_volume += det(p[f[0]], p[f[1]], p[f[2]]);
        six_volume += det(p[f[0]], p[f[2]], p[f[3]]);
    }
    return six_volume > 0;
}

namespace {

bool inside_box(const CellComplex& cx, const LatticePoint& lo, const LatticePoint& hi) {
    for (std::size_t n = 0; n < cx.n_vertices(); ++n)
        for (int a = 0; a < 3; ++a)
            if (cx.position(VertexHandle(n))[a] < lo[a] || cx.position(VertexHandle(n))[a] > hi[a]) return false;
    return true;
}

// What B1-B5 read of the whole complex, computed once for all the vertices checked.
struct BoundaryChecks {
    const CellComplex& cx;
    Incidence inc;
    ValidationReport validation;
    ClippedDual dual;
    std::map<std::uint32_t, std::size_t> hex_of;
    std::map<std::uint32_t, std::string> dual_error;

    BoundaryChecks(const CellComplex& complex, const LatticePoint& lo, const LatticePoint& hi) : cx(complex), inc(complex) {
        // B1: the cells are closed, consistently oriented, conforming (DESIGN.md 4, items 1-2).
        ValidationOptions options;
        options.interior_filter = [](VertexHandle) { return false; };  // interior vertices: compositional.hpp
        validation = validate(cx, options);
        dual = clipped_dual(cx, inc, lo, hi);
        for (std::size_t h = 0; h < dual.hexes.size(); ++h) hex_of[dual.primal_vertex[h].index()] = h;
        for (const DualError& e : dual.errors) dual_error[e.vertex.index()] = e.message;
    }

    // B1-B5 at v, on k >= 1 root planes of `sides`: the first reason it fails, or nothing.
    std::optional<std::string> defect(VertexHandle v, int k, const RootSides& sides) const {
        if (!validation.ok()) return "the cells are not closed, oriented and conforming";
        if (const char* why = star_defect(cx, inc, v, sides)) return why;
        if (const char* why = link_defect(vertex_link(cx, inc, v), k)) return why;
        const auto h = hex_of.find(v.index());
        if (h == hex_of.end()) {
            const auto e = dual_error.find(v.index());
            return e != dual_error.end() ? e->second : "no clipped dual cell";
        }
        if (const char* why = dual_defect(dual, h->second, k, sides)) return why;
        return std::nullopt;
    }
};

}  // namespace

BoundaryVertexReport check_boundary_vertices(const CellComplex& cx, std::int64_t half, const RootSides& sides) {
    BoundaryVertexReport report;
    LatticePoint lo{-half, -half, -half}, hi{half, half, half};
    for (int a = 0; a < 3; ++a) {
        if (sides[static_cast<std::size_t>(a)] > 0) lo[a] = 0;
        if (sides[static_cast<std::size_t>(a)] < 0) hi[a] = 0;
    }
    const BoundaryChecks checks(cx, lo, hi);
    for (std::size_t n = 0; n < cx.n_vertices(); ++n) {
        const VertexHandle v(n);
        const LatticePoint& p = cx.position(v);
        const int k = bits(root_planes(p, sides));
        if (k == 0 || !on_checked_planes(p, half, sides)) continue;
        ++report.checked;
        const auto why = checks.defect(v, k, sides);
        if (!why) continue;
        std::ostringstream os;
        os << "vertex (" << p[0] << ',' << p[1] << ',' << p[2] << "): " << *why;
        report.failures.push_back(os.str());
    }
    return report;
}

std::optional<std::string> boundary_vertex_defect(const CellComplex& cx, const RootSides& sides) {
    const int k = bits(root_planes(LatticePoint{}, sides));
    if (k == 0) return "no root plane through the vertex";
    std::int64_t half = 1;  // the box: the root sides of the planes through v, every cell inside
    for (std::size_t n = 0; n < cx.n_vertices(); ++n)
        for (int a = 0; a < 3; ++a) half = std::max(half, std::abs(cx.position(VertexHandle(n))[a]) + 1);
    LatticePoint lo{-half, -half, -half}, hi{half, half, half};
    for (int a = 0; a < 3; ++a) {
        if (sides[static_cast<std::size_t>(a)] > 0) lo[a] = 0;
        if (sides[static_cast<std::size_t>(a)] < 0) hi[a] = 0;
    }
    for (std::size_t n = 0; n < cx.n_vertices(); ++n) {
        const VertexHandle v(n);
        if (cx.position(v) != LatticePoint{}) continue;
        if (!inside_box(cx, lo, hi)) return "a cell at the vertex is on the outside of a root plane";
        return BoundaryChecks(cx, lo, hi).defect(v, k, sides);
    }
    return "the vertex is in no cell";
}

}  // namespace dualhex
