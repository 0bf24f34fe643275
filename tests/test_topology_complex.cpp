// CellComplex, ComplexBuilder, Incidence, links, the dual and histograms on small
// reference complexes (single cube, 2x2x2 and 3x3x3 blocks).
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>

#include <tbb/task_arena.h>

#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/link.hpp"
#include "dualhex/topology/primitives.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {
namespace {

VertexHandle vertex_at(const CellComplex& k, LatticePoint p) {
    for (std::size_t i = 0; i < k.n_vertices(); ++i)
        if (k.position(VertexHandle(i)) == p) return VertexHandle(i);
    return {};
}

// 8 x the centroid of a cell's distinct vertices (exact).
LatticePoint centroid8(const CellComplex& k, CellHandle c) {
    std::vector<VertexHandle> vs;
    for (HalfFaceHandle h : k.cell_halffaces(c))
        for (VertexHandle v : k.face_vertices(h.face())) vs.push_back(v);
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    LatticePoint s;
    for (VertexHandle v : vs) s = s + k.position(v) * (8 / static_cast<std::int64_t>(vs.size()));
    return s;
}

std::int64_t det(LatticePoint a, LatticePoint b, LatticePoint c) {
    return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
}

// Every corner of every hex has a positive Jacobian sign with dual vertices at centroids.
void expect_positive_hexes(const CellComplex& k, const HexMesh& mesh) {
    static constexpr int kNbr[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                       {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
    for (const auto& hex : mesh.hexes)
        for (int i = 0; i < 8; ++i) {
            const LatticePoint p = centroid8(k, hex[i]);
            EXPECT_GT(det(centroid8(k, hex[kNbr[i][0]]) - p, centroid8(k, hex[kNbr[i][1]]) - p,
                          centroid8(k, hex[kNbr[i][2]]) - p),
                      0);
        }
}

TEST(TopologyBuilder, WeldsVerticesByKey) {
    ComplexBuilder b;
    const VertexHandle a = b.add_vertex({1, 2, 3});
    EXPECT_EQ(b.add_vertex({1, 2, 3}), a);
    EXPECT_NE(b.add_vertex({1, 2, 4}), a);
    EXPECT_EQ(b.find_vertex({1, 2, 3}), a);
    EXPECT_FALSE(b.find_vertex({9, 9, 9}).valid());
    EXPECT_EQ(b.n_vertices(), 2u);
}

TEST(TopologyBuilder, DedupesFacesInBothOrientations) {
    ComplexBuilder b;
    const VertexHandle v0 = b.add_vertex({0, 0, 0}), v1 = b.add_vertex({1, 0, 0}), v2 = b.add_vertex({1, 1, 0}),
                       v3 = b.add_vertex({0, 1, 0});
    const HalfFaceHandle h = b.add_face({v1, v2, v3, v0});
    EXPECT_EQ(h.side(), 0);
    EXPECT_EQ(b.add_face({v3, v0, v1, v2}), h);             // rotated
    EXPECT_EQ(b.add_face({v0, v3, v2, v1}), h.opposite());  // reversed
    EXPECT_EQ(b.add_face({v2, v1, v0, v3}), h.opposite());  // reversed and rotated
    const HalfFaceHandle other = b.add_face({v0, v1, v3, v2});  // same vertices, other cycle
    EXPECT_NE(other.face(), h.face());
    EXPECT_EQ(b.n_faces(), 2u);

    b.add_cell(std::vector<HalfFaceHandle>{h.opposite()});
    const CellComplex k = b.build();
    const auto loop = k.halfface_vertices(h.opposite());
    const auto fwd = k.halfface_vertices(h);
    ASSERT_EQ(loop.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(loop[i], fwd[(4 - i) % 4]);
    EXPECT_EQ(k.n_edges(), 6u);  // 4 sides + 2 diagonals from the second face
    EXPECT_EQ(non_hex_cell_count(k), 1u);  // a cell of one quadrilateral is no hexahedron
}

TEST(TopologyBuilder, RejectsUnknownHandles) {
    ComplexBuilder b;
    EXPECT_THROW(b.add_face({VertexHandle(0)}), std::invalid_argument);
    EXPECT_THROW(b.add_cell(std::vector<HalfFaceHandle>{HalfFaceHandle(3)}), std::invalid_argument);
}

TEST(TopologyComplex, RawConstructionRejectsBadArrays) {
    const std::vector<LatticePoint> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<VertexHandle> tri{VertexHandle(0), VertexHandle(1), VertexHandle(2)};
    EXPECT_NO_THROW(CellComplex(pts, {0, 3}, tri, {0, 1}, {HalfFaceHandle(1)}));
    EXPECT_THROW(CellComplex(pts, {0, 4}, tri, {0}, {}), std::invalid_argument);              // offsets past the end
    EXPECT_THROW(CellComplex(pts, {0, 0, 3}, tri, {0}, {}), std::invalid_argument);           // empty loop
    EXPECT_THROW(CellComplex(pts, {0, 3}, {VertexHandle(0), VertexHandle(1), VertexHandle(7)}, {0}, {}),
                 std::invalid_argument);                                                      // unknown vertex
    EXPECT_THROW(CellComplex(pts, {0, 3}, tri, {0, 1}, {HalfFaceHandle(2)}), std::invalid_argument);  // unknown face
    EXPECT_THROW(CellComplex(pts, {0, 3}, {VertexHandle(0), VertexHandle(-1), VertexHandle(2)}, {0}, {}),
                 std::invalid_argument);                                                      // invalid vertex
    EXPECT_THROW(CellComplex(pts, {0, 3}, tri, {0, 1}, {HalfFaceHandle(-1)}), std::invalid_argument);  // invalid half-face
    try {  // the first out-of-range id is the one named
        CellComplex(pts, {0, 3}, {VertexHandle(0), VertexHandle(9), VertexHandle(8)}, {0}, {});
        ADD_FAILURE() << "no throw";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "CellComplex: face vertex out of range: 9");
    }
}

TEST(TopologyComplex, FaceEdgesFollowTheLoop) {
    const CellComplex k = make_box({0, 0, 0}, {2, 1, 1});
    EXPECT_EQ(k.n_edges(), 20u);
    for (std::size_t f = 0; f < k.n_faces(); ++f) {
        const auto loop = k.face_vertices(FaceHandle(f));
        const auto edges = k.face_edges(FaceHandle(f));
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const auto [a, b] = k.edge_vertices(edges[i]);
            EXPECT_LT(a, b);
            const VertexHandle p = loop[i], q = loop[(i + 1) % loop.size()];
            EXPECT_EQ(std::min(p, q), a);
            EXPECT_EQ(std::max(p, q), b);
        }
    }
}

TEST(TopologyComplex, SingleCube) {
    const CellComplex k = make_box({0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(k.n_vertices(), 8u);
    EXPECT_EQ(k.n_edges(), 12u);
    EXPECT_EQ(k.n_faces(), 6u);
    EXPECT_EQ(k.n_cells(), 1u);
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.checked_vertices, 0u);
    EXPECT_EQ(euler_characteristic(k), 1);
    EXPECT_EQ(face_size_histogram(k), (std::map<int, std::size_t>{{4, 6}}));
    EXPECT_EQ(non_hex_cell_count(k), 0u);
    const Incidence inc(k);
    for (std::size_t f = 0; f < 6; ++f) EXPECT_TRUE(inc.is_boundary(FaceHandle(f)));
    EXPECT_EQ(count_dual(k).interior_vertices, 0u);
}

TEST(TopologyComplex, Block2x2x2) {
    const CellComplex k = make_box({0, 0, 0}, {2, 2, 2});
    EXPECT_EQ(k.n_vertices(), 27u);
    EXPECT_EQ(k.n_cells(), 8u);
    EXPECT_EQ(euler_characteristic(k), 1);
    const Incidence inc(k);
    const VertexHandle centre = vertex_at(k, {1, 1, 1});
    ASSERT_TRUE(centre.valid());
    EXPECT_FALSE(inc.is_boundary(centre));
    EXPECT_EQ(inc.vertex_edges(centre).size(), 6u);
    EXPECT_EQ(inc.vertex_cells(centre).size(), 8u);
    for (EdgeHandle e : inc.vertex_edges(centre)) {
        EXPECT_FALSE(inc.is_boundary(e));
        EXPECT_EQ(inc.edge_cells(e).size(), 4u);
        EXPECT_EQ(inc.edge_faces(e).size(), 4u);
    }
    EXPECT_TRUE(vertex_link(k, inc, centre).is_octahedron());
    EXPECT_TRUE(vertex_link(k, inc, vertex_at(k, {0, 0, 0})).vertices.size() == 3u);
    EXPECT_FALSE(vertex_link(k, inc, vertex_at(k, {0, 0, 0})).is_octahedron());
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.checked_vertices, 1u);
    EXPECT_EQ(r.checked_edges, 6u);  // the 6 spokes at the centre are interior edges
    const DualResult dual = interior_dual(k);
    EXPECT_TRUE(dual.errors.empty());
    ASSERT_EQ(dual.mesh.hexes.size(), 1u);
    expect_positive_hexes(k, dual.mesh);
}

TEST(TopologyComplex, Block3x3x3) {
    const CellComplex k = make_box({0, 0, 0}, {3, 3, 3});
    EXPECT_EQ(euler_characteristic(k), 1);
    const Incidence inc(k);
    std::size_t interior = 0;
    for (std::size_t i = 0; i < k.n_vertices(); ++i) {
        const VertexHandle v(i);
        const LatticePoint p = k.position(v);
        const bool inner = p.x > 0 && p.x < 3 && p.y > 0 && p.y < 3 && p.z > 0 && p.z < 3;
        EXPECT_EQ(inc.is_boundary(v), !inner);
        if (!inner) continue;
        ++interior;
        EXPECT_EQ(inc.vertex_edges(v).size(), 6u);
        EXPECT_TRUE(vertex_link(k, inc, v).is_octahedron());
        EXPECT_FALSE(dual_cube_defect(k, inc, v).has_value());
    }
    EXPECT_EQ(interior, 8u);
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.ok());
    EXPECT_EQ(r.checked_vertices, 8u);
    EXPECT_EQ(r.checked_edges, 12u + 8u * 3u);  // centre-cube edges + spokes to the boundary
    const DualResult dual = interior_dual(k, inc);
    EXPECT_TRUE(dual.errors.empty());
    EXPECT_EQ(dual.mesh.hexes.size(), 8u);
    expect_positive_hexes(k, dual.mesh);
    EXPECT_EQ(interior_dual_edge_valence_histogram(k, inc), (std::map<int, std::size_t>{{4, 6}}));
}

// Edges by the definition (cell_complex.hpp): the distinct unordered pairs of consecutive
// loop vertices, numbered by smaller endpoint, then by first appearance in corner order.
struct ReferenceEdges {
    std::vector<std::array<VertexHandle, 2>> vertices;
    std::vector<EdgeHandle> face_edges;
};

ReferenceEdges reference_edges(const CellComplex& k) {
    std::map<std::pair<VertexHandle, VertexHandle>, std::size_t> first_corner;
    std::vector<std::pair<VertexHandle, VertexHandle>> corner_pair;
    for (std::size_t f = 0; f < k.n_faces(); ++f) {
        const auto loop = k.face_vertices(FaceHandle(f));
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const VertexHandle a = loop[i], b = loop[(i + 1) % loop.size()];
            const auto key = std::minmax(a, b);
            first_corner.try_emplace(key, corner_pair.size());
            corner_pair.push_back(key);
        }
    }
    std::vector<std::pair<std::pair<VertexHandle, std::size_t>, std::pair<VertexHandle, VertexHandle>>> order;
    for (const auto& [key, corner] : first_corner) order.push_back({{key.first, corner}, key});
    std::sort(order.begin(), order.end());
    ReferenceEdges out;
    std::map<std::pair<VertexHandle, VertexHandle>, EdgeHandle> id;
    for (const auto& [rank, key] : order) {
        id[key] = EdgeHandle(out.vertices.size());
        out.vertices.push_back({key.first, key.second});
    }
    for (const auto& key : corner_pair) out.face_edges.push_back(id[key]);
    return out;
}

// Random loops (repeated vertices and degenerate loops included) over few vertices, enough
// faces for the parallel derivation to split them into several blocks.
CellComplex random_loops(std::uint32_t seed) {
    std::mt19937 rng(seed);
    constexpr std::size_t kVertices = 2000, kFaces = 20000;
    std::vector<LatticePoint> positions(kVertices);
    std::vector<std::uint32_t> offsets{0};
    std::vector<VertexHandle> loops;
    for (std::size_t f = 0; f < kFaces; ++f) {
        const std::size_t n = 1 + rng() % 6;
        const std::size_t base = rng() % kVertices;
        for (std::size_t i = 0; i < n; ++i) loops.emplace_back((base + rng() % 40) % kVertices);
        offsets.push_back(static_cast<std::uint32_t>(loops.size()));
    }
    return {std::move(positions), std::move(offsets), std::move(loops), {0}, {}};
}

TEST(TopologyComplex, EdgeNumberingIsTheDefinitionForAnyThreadCount) {
    std::optional<ReferenceEdges> want;
    for (const int threads : {1, 2, 3, 8}) {
        tbb::task_arena arena(threads);
        arena.execute([&] {
            const CellComplex k = random_loops(17);
            if (!want) want = reference_edges(k);  // the same loops every time
            std::vector<std::array<VertexHandle, 2>> edges;
            for (std::size_t e = 0; e < k.n_edges(); ++e) edges.push_back(k.edge_vertices(EdgeHandle(e)));
            std::vector<EdgeHandle> face_edges;
            for (std::size_t f = 0; f < k.n_faces(); ++f)
                for (EdgeHandle e : k.face_edges(FaceHandle(f))) face_edges.push_back(e);
            EXPECT_TRUE(edges == want->vertices) << threads << " threads";
            EXPECT_TRUE(face_edges == want->face_edges) << threads << " threads";
        });
    }
}

TEST(TopologyComplex, LargeBoxHasExactCounts) {
    // Speed is measured in bench/, never here; this checks the counts at a size where
    // hash collisions and bucket growth actually happen.
    constexpr std::size_t n = 40;
    const CellComplex k = make_box({0, 0, 0}, {40, 40, 40});
    EXPECT_EQ(k.n_cells(), n * n * n);
    EXPECT_EQ(k.n_vertices(), (n + 1) * (n + 1) * (n + 1));
    EXPECT_EQ(k.n_faces(), 3 * n * n * (n + 1));
    EXPECT_EQ(k.n_edges(), 3 * n * (n + 1) * (n + 1));
    EXPECT_EQ(euler_characteristic(k), 1);
}

}  // namespace
}  // namespace dualhex
