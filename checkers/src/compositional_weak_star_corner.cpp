// W11 of proofs/README.md: a (vertex, configuration) pair whose 8 leaves all have v as a
// corner of their cube (a *corner pair*) checked leaf by leaf and quadrant by quadrant
// instead of star by star. The stars of such a pair are the products of the leaves'
// pieces, and at parity 111 they run into the millions; but every check the validator
// makes reads one leaf, two leaves across one quadrant of a plane through v, or the star's
// structure at v, which (given the first two) is the same octahedral corner in every star.
//
//   the sign octants around v     a quadrant: the quarter of a plane through v
//   (bit a set: +a side)          between two leaves differing on one axis c
//        +z                             (its face at v: normal to c)
//         |  / +y
//         | /                     pieces (1 leaf):  one cell at v, its 3 edges at v on
//   ------v------ +x                 the 3 half-axes of its octant, its 3 faces at v on
//        /|                          the 3 quadrant planes, every vertex in the octant
//
// Pieces and quadrant tuples are the projections of the pair's stars onto one and two
// leaves: `restricted` keeps those leaves and every status with its implications, so the
// search (W9 (vii)) finds exactly the restrictions of the pair's assignments (Lemma S3).
#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <string>
#include <variant>

#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/validation.hpp"
#include "weak_star_pair.hpp"
#include "window_check.hpp"

namespace dualhex::weak_stars {
namespace {

using Sign = std::array<int, 3>;  // +1 / -1 per axis: the leaf's octant around v

std::optional<Sign> octant_of(const WeakStarInfluence& inf, const LeafBits& b, const LatticePoint& v) {
    const std::int64_t S = cell_size(inf.unit, b.at.leaf.level);
    Sign out{};
    for (int a = 0; a < 3; ++a) {
        const std::int64_t lo = b.at.leaf.cell[static_cast<std::size_t>(a)] * S;
        if (v[a] == lo) out[static_cast<std::size_t>(a)] = 1;
        else if (v[a] == lo + S) out[static_cast<std::size_t>(a)] = -1;
        else return std::nullopt;
    }
    return out;
}

int zeros(const LatticePoint& p) { return (p.x == 0) + (p.y == 0) + (p.z == 0); }

// The sum of a loop's vertex positions (v at the origin): its coordinate a is 0 iff every
// vertex of a loop inside one closed octant lies on the plane a = 0.
LatticePoint loop_sum(const CellComplex& cx, std::span<const VertexHandle> loop) {
    LatticePoint s{};
    for (VertexHandle h : loop) s = s + cx.position(h);
    return s;
}

std::optional<VertexHandle> vertex_at_origin(const CellComplex& cx) {
    for (std::size_t i = 0; i < cx.n_vertices(); ++i)
        if (cx.position(VertexHandle(i)) == LatticePoint{}) return VertexHandle(i);
    return std::nullopt;
}

// The axis of an edge at v along a half-axis of `sign`'s octant, or -1.
int half_axis(const CellComplex& cx, EdgeHandle e, VertexHandle v, const Sign& sign) {
    const auto [a, b] = cx.edge_vertices(e);
    const LatticePoint w = cx.position(a == v ? b : a);
    if (zeros(w) != 2) return -1;
    for (int c = 0; c < 3; ++c)
        if (w[c] != 0) return w[c] * sign[static_cast<std::size_t>(c)] > 0 ? c : -1;
    return -1;
}

// Checks (1)-(2) of validate (cells, conformity); the first violation, or nothing.
std::optional<std::string> validation_defect(const CellComplex& cx) {
    ValidationOptions o;
    o.check_interior = false;
    const ValidationReport r = validate(cx, o);
    if (r.ok()) return std::nullopt;
    return std::string("validation: ") + to_string(r.violations.front().kind) + " " + r.violations.front().message;
}

}  // namespace

std::optional<std::string> corner_piece_defect(const CellComplex& cx, const std::array<int, 3>& sign) {
    if (cx.n_cells() != 1) return std::to_string(cx.n_cells()) + " cells at v (a corner piece has one)";
    const auto v = vertex_at_origin(cx);
    if (!v) return std::string("v is not a vertex");
    for (std::size_t i = 0; i < cx.n_vertices(); ++i) {
        const LatticePoint q = cx.position(VertexHandle(i));
        for (int a = 0; a < 3; ++a)
            if (q[a] * sign[static_cast<std::size_t>(a)] < 0) return std::string("a vertex outside the leaf's octant");
    }
    const Incidence inc(cx);
    const auto edges = inc.vertex_edges(*v);
    std::set<int> axes;
    for (EdgeHandle e : edges) axes.insert(half_axis(cx, e, *v, sign));
    if (edges.size() != 3 || axes != std::set<int>{0, 1, 2}) return std::string("the edges at v are not the octant's 3 half-axes");
    const auto faces = inc.vertex_faces(*v);
    if (faces.size() != 3) return std::to_string(faces.size()) + " faces at v";
    for (FaceHandle f : faces) {
        const LatticePoint s = loop_sum(cx, cx.face_vertices(f));
        if (zeros(s) != 1) return std::string("a face at v off the quadrant planes");
    }
    for (std::size_t f = 0; f < cx.n_faces(); ++f)
        if (zeros(loop_sum(cx, cx.face_vertices(FaceHandle(f)))) > 1) return std::string("a face on an axis");
    std::set<std::size_t> cell_vertices;
    for (HalfFaceHandle h : cx.cell_halffaces(CellHandle(0)))
        for (VertexHandle q : cx.face_vertices(h.face())) cell_vertices.insert(q.idx);
    LatticePoint s{};
    for (std::size_t q : cell_vertices) s = s + cx.position(VertexHandle(q));
    if (zeros(s) != 0) return std::string("a flat cell");
    if (auto d = validation_defect(cx)) return d;
    return std::nullopt;
}

std::optional<std::string> corner_quadrant_defect(const CellComplex& cx) {
    if (auto d = validation_defect(cx)) return d;
    const auto v = vertex_at_origin(cx);
    if (!v) return std::string("v is not a vertex");
    const Incidence inc(cx);
    const auto faces = inc.vertex_faces(*v);
    const auto shared = std::count_if(faces.begin(), faces.end(), [&](FaceHandle f) { return inc.face_cells(f).size() == 2; });
    if (inc.vertex_edges(*v).size() != 4 || faces.size() != 5 || shared != 1)
        return "the two leaves' faces and edges at v do not meet in one face: " + std::to_string(inc.vertex_edges(*v).size()) +
               " edges, " + std::to_string(faces.size()) + " faces at v";
    return std::nullopt;
}

Pair restricted(const Pair& p, const std::vector<std::size_t>& keep) {
    Pair out{p.v, {}, p.n_shared, p.implies};
    for (std::size_t n : keep) out.leaves.push_back(p.leaves[n]);
    return out;
}

bool is_corner_pair(const WeakStarInfluence& inf, const Pair& p, const LatticePoint& v_world) {
    return p.leaves.size() == 8 &&
           std::all_of(p.leaves.begin(), p.leaves.end(), [&](const LeafBits& b) { return octant_of(inf, b, v_world).has_value(); });
}

namespace {

// Sign octant (bit a: +a) -> leaf index, or the reason the pair is no corner pair.
std::variant<std::array<std::size_t, 8>, std::string> leaf_of_octant(const WeakStarInfluence& inf, const Pair& p,
                                                                     const LatticePoint& v) {
    std::array<std::size_t, 8> leaf_of{};
    std::set<int> octants;
    for (std::size_t n = 0; n < p.leaves.size(); ++n) {
        const auto sign = octant_of(inf, p.leaves[n], v);
        if (!sign) return "leaf " + std::to_string(n) + " does not have v as a corner";
        const int o = ((*sign)[0] > 0) | ((*sign)[1] > 0) << 1 | ((*sign)[2] > 0) << 2;
        octants.insert(o);
        leaf_of[static_cast<std::size_t>(o)] = n;
    }
    if (p.leaves.size() != 8 || octants.size() != 8) return std::string("not 8 leaves, one per octant");
    return leaf_of;
}

}  // namespace

CornerCheck check_corner_pair(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                              const PieceCubes& cubes, const Pair& p, const LatticePoint& v, long limit) {
    CornerCheck out;
    const auto octants = leaf_of_octant(inf, p, v);
    if (const auto* why = std::get_if<std::string>(&octants)) return out.fail(*why);
    const auto& leaf_of = std::get<std::array<std::size_t, 8>>(octants);
    const auto complex_of = [&](const Pair& sub, const std::vector<int>& contexts) {
        return build_star(inf, rule, cache, sub, v, contexts).complex;
    };
    // One leaf: every piece its statuses allow.
    for (int o = 0; o < 8; ++o) {
        const Pair one = restricted(p, {leaf_of[static_cast<std::size_t>(o)]});
        const Sign sign{o & 1 ? 1 : -1, o & 2 ? 1 : -1, o & 4 ? 1 : -1};
        for (const auto& [pieces, contexts] : stars_by_search(cubes, one, out.search_nodes, limit)) {
            ++out.pieces;
            if (auto d = corner_piece_defect(complex_of(one, contexts), sign)) return out.fail("octant " + std::to_string(o) + ": " + *d);
        }
    }
    // Two leaves across a quadrant: every pair of pieces their statuses allow jointly.
    for (int o = 0; o < 8; ++o)
        for (int c = 0; c < 3; ++c) {
            const int o2 = o ^ (1 << c);
            if (o2 < o) continue;
            const Pair two = restricted(p, {leaf_of[static_cast<std::size_t>(o)], leaf_of[static_cast<std::size_t>(o2)]});
            for (const auto& [pieces, contexts] : stars_by_search(cubes, two, out.search_nodes, limit)) {
                ++out.quadrant_tuples;
                if (auto d = corner_quadrant_defect(complex_of(two, contexts)))
                    return out.fail("octants " + std::to_string(o) + ", " + std::to_string(o2) + ": " + *d);
            }
        }
    // The structure at v, now the same in every star: one star of the pair, fully checked.
    const Stars first = stars_by_search(cubes, p, out.search_nodes, limit, 1);
    if (first.empty()) return out.fail("no star");
    const auto& contexts = first.begin()->second;
    const ConfigurationReport r = detail::check(
        0, [&] { return build_star(inf, rule, cache, p, v, contexts); }, [](const LatticePoint& q) { return q == LatticePoint{}; },
        [](const CellComplex& cx, std::span<const VertexHandle> loop) {
            return std::none_of(loop.begin(), loop.end(), [&](VertexHandle h) { return cx.position(h) == LatticePoint{}; });
        });
    if (!r.ok() || r.checked_vertices != 1) return out.fail("the representative star: " + r.summary());
    out.passed = true;
    return out;
}

long corner_witness_stars(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                          const PieceCubes& cubes, const Pair& p, const LatticePoint& v, long limit,
                          const std::function<void(int, int, const std::vector<int>&, const ConfigurationComplex&)>& tell) {
    const auto octants = leaf_of_octant(inf, p, v);
    if (const auto* why = std::get_if<std::string>(&octants)) throw std::invalid_argument("corner_witness_stars: " + *why);
    const auto& leaf_of = std::get<std::array<std::size_t, 8>>(octants);
    long nodes = 0, told = 0;
    for (int o = 0; o < 8; ++o)
        for (int c = 0; c < 3; ++c) {
            const int o2 = o ^ (1 << c);
            if (o2 < o) continue;
            std::vector<std::size_t> order{leaf_of[static_cast<std::size_t>(o)], leaf_of[static_cast<std::size_t>(o2)]};
            for (std::size_t n = 0; n < 8; ++n)
                if (n != order[0] && n != order[1]) order.push_back(n);
            const Pair two = restricted(p, {order[0], order[1]}), all = restricted(p, order);
            for (const auto& [pieces, contexts] : stars_by_search(cubes, two, nodes, limit)) {
                // Lemma S3: the two leaves' pieces are a projection of a star, which the search
                // with them first therefore finds
                const Stars witness = stars_by_search(cubes, all, nodes, limit, 1, pieces);
                if (witness.empty()) throw std::logic_error("corner_witness_stars: a quadrant tuple no star extends");
                if (!std::equal(pieces.begin(), pieces.end(), witness.begin()->first.begin()))
                    throw std::logic_error("corner_witness_stars: the star found does not have the quadrant tuple");
                tell(o, o2, pieces, build_star(inf, rule, cache, all, v, witness.begin()->second));
                ++told;
            }
        }
    return told;
}

}  // namespace dualhex::weak_stars
