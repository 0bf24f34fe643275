// Chain-crossing variants: the prototype's parts (schemes/derivation/elems.py) as data and
// their assembly per over/under assignment. The lid by complement is variant_lid.cpp, the
// canonical forms variant_forms.cpp, the loop tools both use variant_loops.cpp.
#include "dualhex/schemes/variants.hpp"

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>
#include <utility>

#include "dualhex/topology/complex_builder.hpp"
#include "variant_loops.hpp"

namespace dualhex::variants {
namespace {

constexpr std::int64_t U = kLeaf, H = kHalf, L = kLow;

using namespace detail;

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

}  // namespace dualhex::variants
