// Chain-crossing variants: the prototype's parts (schemes/derivation/elems.py) as data, the
// assembly per over/under assignment, the lid by complement (autolid.py) and canonical forms.
#include "dualhex/schemes/variants.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>
#include <utility>

#include "dualhex/topology/complex_builder.hpp"

namespace dualhex::variants {
namespace {

constexpr std::int64_t U = kLeaf, H = kHalf, L = kLow;

using Faces = std::vector<Loop>;

LatticePoint cross(const LatticePoint& a, const LatticePoint& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
std::int64_t dot(const LatticePoint& a, const LatticePoint& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Faces map_points(const Faces& faces, const std::function<LatticePoint(const LatticePoint&)>& f) {
    Faces out = faces;
    for (auto& loop : out)
        for (auto& p : loop) p = f(p);
    return out;
}
// elems.py: swyz (y <-> z), rot ((x,y,z) -> (z,x,y)), reflect over x and z (F -> Fo).
Faces swyz(const Faces& f) { return map_points(f, [](const LatticePoint& p) { return LatticePoint{p.x, p.z, p.y}; }); }
Faces rot(const Faces& f) { return map_points(f, [](const LatticePoint& p) { return LatticePoint{p.z, p.x, p.y}; }); }
Faces swxz(const Faces& f) { return map_points(f, [](const LatticePoint& p) { return LatticePoint{p.z, p.y, p.x}; }); }
Faces reflect_xz(const Faces& f) {
    return map_points(f, [](const LatticePoint& p) { return LatticePoint{U - p.x, p.y, U - p.z}; });
}

// ---- the parts ------------------------------------------------------------------------

// elems.F(): the flat element in its derivation frame (crossing at the origin); Fo reflects
// it over x and z so that the crossing is at the far corner (12,0,12).
struct FlatParts {
    Faces p1, p2, q;
};
FlatParts flat_parts() {
    const LatticePoint O{0, 0, 0}, hx{H, 0, 0}, X1{U, 0, 0}, hz{0, 0, H}, Z1{0, 0, U}, m{H, 0, H}, e1{U, 0, H},
        e2{H, 0, U};
    const LatticePoint a0{0, L, 0}, a1{H, L, 0}, a2{U, H, 0}, b0{0, H, 0}, b2{0, H, U};
    FlatParts f;
    f.p1 = {{O, hz, a0}, {hx, m, a1}, {O, hx, m, hz}, {O, hx, a1, a0}, {hz, m, a1, a0}};
    f.p2 = {{hx, m, a1}, {X1, e1, a2}, {hx, X1, e1, m}, {hx, X1, a2, a1}, {m, e1, a2, a1}};
    f.q = {{a0, a1, b0}, {Z1, e2, b2}, {a0, b0, b2, Z1, hz}, {hz, m, a1, a0}, {hz, m, e2, Z1}, {b0, a1, m, e2, b2}};
    return {reflect_xz(f.p1), reflect_xz(f.p2), reflect_xz(f.q)};
}

// elems.Eo(): the turning chain's prism under the crossing on face y = 0 (P1), the chain over
// z = 12 on top of it (Bq) and the bend below both crossings (Ab).
struct EdgeParts {
    Faces P1, Bq, bend_LL;
};
EdgeParts edge_parts() {
    const LatticePoint r1{U, L, U}, r2{U, L, H}, r3{U, H, L};
    EdgeParts e;
    e.P1 = {{{H, 0, H}, {U, 0, H}, {U, 0, U}, {H, 0, U}},
            {{U, 0, H}, {U, 0, U}, r1, r2},
            {{H, 0, U}, {U, 0, U}, r1},
            {{H, 0, H}, {U, 0, H}, r2},
            {{H, 0, H}, {H, 0, U}, r1, r2}};
    e.bend_LL = {{{H, 0, 0}, {U, 0, 0}, {U, 0, H}, {H, 0, H}},
                 {{H, 0, 0}, {U, 0, 0}, {U, H, 0}, {H, H, 0}},
                 {{U, 0, 0}, {U, 0, H}, r2, r3, {U, H, 0}},
                 {{H, 0, H}, {U, 0, H}, r2},
                 {{H, H, 0}, {U, H, 0}, r3},
                 {{H, 0, H}, {H, 0, 0}, {H, H, 0}, r3, r2}};
    e.Bq = {{{0, 0, H}, {H, 0, H}, {H, 0, U}, {0, 0, U}},
            {{0, 0, H}, {0, 0, U}, {0, H, U}},
            {{0, 0, U}, {H, 0, U}, r1, {U, H, U}, {0, H, U}},
            {r1, r2, {U, H, U}},
            {{H, 0, H}, {H, 0, U}, r1, r2},
            {{0, 0, H}, {H, 0, H}, r2, {U, H, U}, {0, H, U}}};
    return e;
}

// elems._VS_parts(): the chain over y = 12 passing below on face z = 0 (p1c, p2c) and the bend
// below on face y = 0, above on face z = 0.
struct LowZParts {
    Faces p1c, p2c, bend_LU;
};
LowZParts low_z_parts() {
    const LatticePoint c1{U, U, L}, c2{H, U, L}, r2{U, L, H};
    LowZParts v;
    v.p1c = {{{U, U, 0}, {U, H, 0}, c1},
             {{H, U, 0}, {H, H, 0}, c2},
             {{U, U, 0}, {H, U, 0}, {H, H, 0}, {U, H, 0}},
             {{U, U, 0}, {H, U, 0}, c2, c1},
             {{U, H, 0}, {H, H, 0}, c2, c1}};
    v.p2c = {{{H, U, 0}, {H, H, 0}, c2},
             {{0, U, 0}, {0, H, 0}, {0, U, H}},
             {{H, U, 0}, {0, U, 0}, {0, H, 0}, {H, H, 0}},
             {{H, U, 0}, {0, U, 0}, {0, U, H}, c2},
             {{H, H, 0}, {0, H, 0}, {0, U, H}, c2}};
    v.bend_LU = {{{H, 0, 0}, {U, 0, 0}, {U, 0, H}, {H, 0, H}},
                 {{H, 0, 0}, {U, 0, 0}, {U, H, 0}, {H, H, 0}},
                 {{U, 0, 0}, {U, 0, H}, r2, {U, U, H}, c1, {U, H, 0}},
                 {{H, 0, H}, {U, 0, H}, r2},
                 {{U, H, 0}, {H, H, 0}, c2, c1},
                 {c1, c2, {U, U, H}},
                 {{H, 0, H}, {H, 0, 0}, {H, H, 0}, c2, {U, U, H}, r2}};
    return v;
}

// elems.bend_UU(): the bend above both crossings.
Faces bend_UU() {
    const LatticePoint c1{U, U, L}, c2{H, U, L}, b1{U, L, U}, b2{H, L, U};
    return {{{H, 0, 0}, {U, 0, 0}, {U, 0, H}, {H, 0, H}},
            {{H, 0, 0}, {U, 0, 0}, {U, H, 0}, {H, H, 0}},
            {{U, 0, 0}, {U, 0, H}, b1, {U, H, U}, {U, U, H}, c1, {U, H, 0}},
            {{U, 0, H}, {H, 0, H}, b2, b1},
            {{U, H, 0}, {H, H, 0}, c2, c1},
            {b1, b2, {U, H, U}},
            {c1, c2, {U, U, H}},
            {{H, 0, 0}, {H, 0, H}, b2, {U, H, U}, {U, U, H}, c2, {H, H, 0}}};
}

Faces bend(bool below_y, bool below_z) {
    if (below_y && below_z) return edge_parts().bend_LL;
    if (below_y) return low_z_parts().bend_LU;
    if (below_z) return swyz(low_z_parts().bend_LU);
    return bend_UU();
}

// ---- the lid by complement (autolid.py) -------------------------------------------------

// p strictly inside the segment ab (exact).
bool on_segment(const LatticePoint& p, const LatticePoint& a, const LatticePoint& b) {
    if (p == a || p == b) return false;
    const LatticePoint d = b - a, e = p - a;
    if (!(cross(d, e) == LatticePoint{0, 0, 0})) return false;
    const std::int64_t t = dot(e, d);
    return t > 0 && t < dot(d, d);
}

Loop insert_tjunctions(const Loop& loop, const std::set<LatticePoint>& verts) {
    Loop out;
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
        const LatticePoint& a = loop[k];
        const LatticePoint& b = loop[(k + 1) % n];
        out.push_back(a);
        std::vector<LatticePoint> mids;
        for (const auto& v : verts)
            if (on_segment(v, a, b)) mids.push_back(v);
        std::sort(mids.begin(), mids.end(), [&](const LatticePoint& u, const LatticePoint& w) {
            return dot(u - a, b - a) < dot(w - a, b - a);
        });
        out.insert(out.end(), mids.begin(), mids.end());
    }
    return out;
}

// cx.canon_face: the loop rotated to its smallest point, in the smaller direction.
Loop canonical_loop(const Loop& loop) {
    const std::size_t n = loop.size();
    const std::size_t i = static_cast<std::size_t>(std::min_element(loop.begin(), loop.end()) - loop.begin());
    Loop a(n), b(n);
    for (std::size_t k = 0; k < n; ++k) {
        a[k] = loop[(i + k) % n];
        b[k] = loop[(i + n - k) % n];
    }
    return std::min(a, b);
}

// (axis, value) of the leaf face containing the loop, or axis -1.
std::pair<int, std::int64_t> leaf_face_of(const Loop& f) {
    for (int axis = 0; axis < 3; ++axis)
        for (std::int64_t v : {std::int64_t{0}, U})
            if (std::all_of(f.begin(), f.end(), [&](const LatticePoint& p) { return p[axis] == v; })) return {axis, v};
    return {-1, 0};
}

using UEdge = std::pair<LatticePoint, LatticePoint>;
UEdge uedge(const LatticePoint& a, const LatticePoint& b) { return a < b ? UEdge{a, b} : UEdge{b, a}; }

std::string point_string(const LatticePoint& p) {
    std::ostringstream os;
    os << p;
    return os.str();
}

// cx.orient_cell: consistent by BFS over shared edges, outward by the signed volume.
Faces orient_cell(Faces faces, const std::string& label) {
    const std::size_t n = faces.size();
    std::map<UEdge, std::vector<std::size_t>> edge_faces;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < faces[i].size(); ++k)
            edge_faces[uedge(faces[i][k], faces[i][(k + 1) % faces[i].size()])].push_back(i);
    for (const auto& [e, fl] : edge_faces)
        if (fl.size() != 2)
            throw VariantConstructionError("cell '" + label + "': edge " + point_string(e.first) + "-" +
                                           point_string(e.second) + " in " + std::to_string(fl.size()) + " faces");
    auto has_directed = [](const Loop& f, const LatticePoint& a, const LatticePoint& b) {
        for (std::size_t k = 0; k < f.size(); ++k)
            if (f[k] == a && f[(k + 1) % f.size()] == b) return true;
        return false;
    };
    std::vector<bool> done(n, false);
    std::vector<std::size_t> stack{0};
    done[0] = true;
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        const Loop fi = faces[i];
        for (std::size_t k = 0; k < fi.size(); ++k) {
            const LatticePoint &a = fi[k], &b = fi[(k + 1) % fi.size()];
            for (std::size_t j : edge_faces[uedge(a, b)]) {
                if (j == i || done[j]) continue;
                if (has_directed(faces[j], a, b)) std::reverse(faces[j].begin(), faces[j].end());
                done[j] = true;
                stack.push_back(j);
            }
        }
    }
    if (!std::all_of(done.begin(), done.end(), [](bool d) { return d; }))
        throw VariantConstructionError("cell '" + label + "': faces disconnected");
    std::int64_t volume6 = 0;
    for (const auto& f : faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k) volume6 += dot(f[0], cross(f[k], f[k + 1]));
    if (volume6 == 0) throw VariantConstructionError("cell '" + label + "': zero volume");
    if (volume6 < 0)
        for (auto& f : faces) std::reverse(f.begin(), f.end());
    return faces;
}

std::vector<PartCell> oriented(std::vector<PartCell> cells) {
    for (auto& c : cells) c.faces = orient_cell(std::move(c.faces), c.label);
    return cells;
}

// elems.E_variant / unit_x pieces.
std::vector<PartCell> edge_cells(bool below_y, bool below_z) {
    const EdgeParts e = edge_parts();
    std::vector<PartCell> cells;
    if (below_y) {
        cells.push_back({"P1y", e.P1});
        cells.push_back({"By", e.Bq});
    } else {
        const FlatParts f = flat_parts();
        cells.push_back({"lowy1", f.p1});
        cells.push_back({"lowy2", f.p2});
    }
    if (below_z) {
        cells.push_back({"P1z", swyz(e.P1)});
        cells.push_back({"Cz", swyz(e.Bq)});
    } else {
        const LowZParts v = low_z_parts();
        cells.push_back({"lowz1", v.p1c});
        cells.push_back({"lowz2", v.p2c});
    }
    cells.push_back({"bend", bend(below_y, below_z)});
    return cells;
}

// elems.unit_x(sy, sz): the turning chain around the x-edge at a concave corner: its prisms
// under the crossings where it is below, and its bend.
std::vector<PartCell> corner_unit(char axis, bool below_y, bool below_z) {
    const EdgeParts e = edge_parts();
    std::vector<PartCell> cells;
    const std::string t(1, axis);
    if (below_y) cells.push_back({"P1y_" + t, e.P1});
    if (below_z) cells.push_back({"P1z_" + t, swyz(e.P1)});
    cells.push_back({"bend_" + t, bend(below_y, below_z)});
    return cells;
}

Variant finish(Region region, const std::string& assignment, const std::string& name, std::vector<PartCell> cells) {
    Variant v;
    v.region = region;
    v.assignment = assignment;
    v.name = name;
    v.cells = oriented(with_lid(std::move(cells)));
    for (std::size_t k = 0; k < v.cells.size(); ++k) {
        v.labels.push_back(v.cells[k].label);
        if (v.cells[k].label.rfind("bend", 0) == 0) v.bend_cells.push_back(static_cast<int>(k));
    }
    v.complex = build_complex(v.cells);
    return v;
}

}  // namespace

const char* to_string(Region region) {
    switch (region) {
        case Region::Flat: return "flat";
        case Region::ConcaveEdge: return "concave_edge";
        case Region::ConcaveCorner: return "concave_corner";
    }
    return "?";
}

std::size_t assignment_count(Region region) {
    return region == Region::Flat ? 2 : region == Region::ConcaveEdge ? 4 : 8;
}

std::vector<PartCell> with_lid(std::vector<PartCell> cells, const std::string& lid_label) {
    std::set<LatticePoint> verts;
    for (const auto& c : cells)
        for (const auto& f : c.faces) verts.insert(f.begin(), f.end());
    for (std::int64_t a : {std::int64_t{0}, U})
        for (std::int64_t b : {std::int64_t{0}, U})
            for (std::int64_t d : {std::int64_t{0}, U}) verts.insert({a, b, d});
    for (auto& c : cells)
        for (auto& f : c.faces) f = insert_tjunctions(f, verts);

    std::map<Loop, std::size_t> count;  // canonical loop -> uses
    std::vector<Loop> order;            // canonical loops in first-use order
    std::map<Loop, Loop> rep;
    for (const auto& c : cells)
        for (const auto& f : c.faces) {
            Loop key = canonical_loop(f);
            if (count[key]++ == 0) order.push_back(key);
            rep[key] = f;
        }
    PartCell lid{lid_label, {}};
    for (const auto& key : order)
        if (count[key] == 1 && leaf_face_of(rep[key]).first < 0) lid.faces.push_back(rep[key]);

    for (int axis = 0; axis < 3; ++axis)
        for (std::int64_t val : {std::int64_t{0}, U}) {
            int o0 = -1, o1 = -1;
            for (int i = 0; i < 3; ++i)
                if (i != axis) (o0 < 0 ? o0 : o1) = i;
            auto P = [&](std::int64_t s, std::int64_t t) {
                LatticePoint p;
                p[axis] = val;
                p[o0] = s;
                p[o1] = t;
                return p;
            };
            const Loop sq = insert_tjunctions({P(0, 0), P(U, 0), P(U, U), P(0, U)}, verts);
            std::map<UEdge, int> edges;
            std::vector<UEdge> edge_order;
            auto add = [&](const Loop& f) {
                for (std::size_t k = 0; k < f.size(); ++k) {
                    const UEdge e = uedge(f[k], f[(k + 1) % f.size()]);
                    if (edges[e]++ == 0) edge_order.push_back(e);
                }
            };
            add(sq);
            for (const auto& key : order)
                if (leaf_face_of(rep[key]) == std::pair<int, std::int64_t>{axis, val}) add(rep[key]);
            std::map<LatticePoint, std::vector<LatticePoint>> adj;
            std::vector<LatticePoint> adj_order;
            for (const auto& e : edge_order) {
                if (edges[e] != 1) continue;
                for (const auto& [p, q] : {std::pair{e.first, e.second}, std::pair{e.second, e.first}}) {
                    if (adj[p].empty()) adj_order.push_back(p);
                    adj[p].push_back(q);
                }
            }
            std::set<LatticePoint> seen;
            for (const auto& start : adj_order) {
                if (seen.count(start)) continue;
                Loop loop{start};
                seen.insert(start);
                LatticePoint prev = start, cur = start;
                bool first = true;
                while (true) {
                    if (adj[cur].size() != 2)
                        throw VariantConstructionError("non-simple lid region on leaf face " + std::to_string(axis) +
                                                       "=" + std::to_string(val) + " at " + point_string(cur));
                    const LatticePoint next = (first || !(adj[cur][0] == prev)) ? adj[cur][0] : adj[cur][1];
                    first = false;
                    if (next == start) break;
                    loop.push_back(next);
                    seen.insert(next);
                    prev = cur;
                    cur = next;
                }
                lid.faces.push_back(std::move(loop));
            }
        }
    cells.push_back(std::move(lid));
    return cells;
}

CellComplex build_complex(const std::vector<PartCell>& cells) {
    ComplexBuilder builder;
    for (const auto& c : cells) builder.add_cell_from_loops(c.faces);
    return std::move(builder).build();
}

ElementData Variant::element_data() const { return element_from_complex(name, kLeaf, complex, labels); }

std::vector<std::string> assignments(Region region) {
    switch (region) {
        case Region::Flat: return {"x", "z"};
        case Region::ConcaveEdge: return {"LL", "LU", "UL", "UU"};
        case Region::ConcaveCorner: {
            std::vector<std::string> out;
            for (char ly : {'X', 'Z'})
                for (char lz : {'X', 'Y'})
                    for (char lx : {'Y', 'Z'}) out.push_back(std::string{ly, lz, lx});
            return out;
        }
    }
    return {};
}

Variant build_variant(Region region, const std::string& a) {
    const auto known = assignments(region);
    if (std::find(known.begin(), known.end(), a) == known.end())
        throw std::invalid_argument(std::string("unknown ") + to_string(region) + " assignment '" + a + "'");
    switch (region) {
        case Region::Flat: {
            const FlatParts f = flat_parts();
            std::vector<PartCell> cells{{"p1", f.p1}, {"p2", f.p2}, {"q", f.q}};
            if (a == "z")
                for (auto& c : cells) c.faces = swxz(c.faces);
            return finish(region, a, "flat-" + a, std::move(cells));
        }
        case Region::ConcaveEdge:
            return finish(region, a, "edge-" + a, edge_cells(a[0] == 'L', a[1] == 'L'));
        case Region::ConcaveCorner: {
            const char ly = a[0], lz = a[1], lx = a[2];
            std::vector<PartCell> cells = corner_unit('x', ly == 'X', lz == 'X');
            for (auto c : corner_unit('y', lz == 'Y', lx == 'Y')) {
                c.faces = rot(c.faces);
                cells.push_back(std::move(c));
            }
            for (auto c : corner_unit('z', lx == 'Z', ly == 'Z')) {
                c.faces = rot(rot(c.faces));
                cells.push_back(std::move(c));
            }
            return finish(region, a, "corner-" + a, std::move(cells));
        }
    }
    throw std::invalid_argument("unknown region");
}

std::vector<Variant> region_variants(Region region) {
    std::vector<Variant> out;
    for (const auto& a : assignments(region)) out.push_back(build_variant(region, a));
    return out;
}

std::string shipped_counterpart(Region region, const std::string& a) {
    if (region == Region::Flat && a == "x") return "F";
    if (region == Region::ConcaveEdge && a == "LL") return "E";
    if (region == Region::ConcaveEdge && a == "LU") return "VS";
    if (region == Region::ConcaveCorner && a == "XYZ") return "VC";
    return "";
}

ComplexForm complex_form(const CellComplex& complex, const CubeSymmetry& symmetry) {
    ComplexForm form;
    form.reserve(complex.n_cells());
    for (std::size_t c = 0; c < complex.n_cells(); ++c) {
        std::vector<std::vector<LatticePoint>> cell;
        for (auto h : complex.cell_halffaces(CellHandle(c))) {
            Loop loop;
            for (auto v : complex.face_vertices(h.face())) loop.push_back(symmetry.apply(complex.position(v)));
            cell.push_back(canonical_loop(loop));
        }
        std::sort(cell.begin(), cell.end());
        form.push_back(std::move(cell));
    }
    std::sort(form.begin(), form.end());
    return form;
}

const std::array<CubeSymmetry, 6>& leaf_symmetries() {
    static const std::array<CubeSymmetry, 6> kSymmetries = {
        CubeSymmetry({0, 1, 2}, {1, 1, 1}), CubeSymmetry({0, 2, 1}, {1, 1, 1}), CubeSymmetry({1, 0, 2}, {1, 1, 1}),
        CubeSymmetry({1, 2, 0}, {1, 1, 1}), CubeSymmetry({2, 0, 1}, {1, 1, 1}), CubeSymmetry({2, 1, 0}, {1, 1, 1})};
    return kSymmetries;
}

ComplexForm canonical_form(const CellComplex& complex) {
    ComplexForm best;
    bool first = true;
    for (const auto& s : leaf_symmetries()) {
        ComplexForm f = complex_form(complex, s);
        if (first || f < best) best = std::move(f);
        first = false;
    }
    return best;
}

std::vector<CubeSymmetry> symmetries_mapping(const CellComplex& a, const CellComplex& b) {
    const ComplexForm fa = complex_form(a);
    std::vector<CubeSymmetry> out;
    for (const auto& s : leaf_symmetries())
        if (complex_form(b, s) == fa) out.push_back(s);
    return out;
}

std::map<int, std::size_t> cells_face_histogram(const CellComplex& complex, const std::vector<int>& cells) {
    std::set<std::size_t> faces;
    for (int c : cells)
        for (auto h : complex.cell_halffaces(CellHandle(static_cast<std::size_t>(c)))) faces.insert(h.face().index());
    std::map<int, std::size_t> hist;
    for (std::size_t f : faces) ++hist[static_cast<int>(complex.face_vertices(FaceHandle(f)).size())];
    return hist;
}

}  // namespace dualhex::variants
