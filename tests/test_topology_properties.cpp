// Property tests: random boxes of unit cubes, and their images under random cube
// symmetries plus translations.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/dual.hpp"
#include "dualhex/topology/histograms.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/primitives.hpp"
#include "dualhex/topology/transform.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {
namespace {

struct Box {
    std::array<int, 3> n;
    LatticePoint offset;
};

Box random_box() {
    return {{*rc::gen::inRange(1, 6), *rc::gen::inRange(1, 6), *rc::gen::inRange(1, 6)},
            {*rc::gen::inRange(-50, 51), *rc::gen::inRange(-50, 51), *rc::gen::inRange(-50, 51)}};
}

// Built cell by cell through the builder, in a random order, so welding and face dedupe
// are exercised (make_box is not used on purpose).
CellComplex build_box(const Box& box, std::uint64_t order_seed) {
    std::vector<LatticePoint> corners;
    for (int i = 0; i < box.n[0]; ++i)
        for (int j = 0; j < box.n[1]; ++j)
            for (int k = 0; k < box.n[2]; ++k) corners.push_back(box.offset + LatticePoint{i, j, k});
    for (std::size_t i = corners.size(); i > 1; --i) {  // deterministic shuffle (LCG)
        order_seed = order_seed * 6364136223846793005ULL + 1442695040888963407ULL;
        std::swap(corners[i - 1], corners[(order_seed >> 33) % i]);
    }
    ComplexBuilder b;
    for (const LatticePoint& c : corners) b.add_cell_from_loops(cube_loops(c));
    return b.build();
}

std::size_t expected_interior(const Box& box) {
    return static_cast<std::size_t>((box.n[0] - 1) * (box.n[1] - 1) * (box.n[2] - 1));
}

void check_box_properties(const CellComplex& k, std::size_t interior) {
    const ValidationReport r = validate(k);
    RC_ASSERT(r.ok());
    RC_ASSERT(r.checked_vertices == interior);
    const Incidence inc(k);
    for (std::size_t i = 0; i < k.n_vertices(); ++i)
        if (!inc.is_boundary(VertexHandle(i))) RC_ASSERT(inc.vertex_edges(VertexHandle(i)).size() == 6u);
    for (std::size_t i = 0; i < k.n_edges(); ++i)
        if (!inc.is_boundary(EdgeHandle(i))) RC_ASSERT(inc.edge_cells(EdgeHandle(i)).size() == 4u);
    const DualResult dual = interior_dual(k, inc);
    RC_ASSERT(dual.errors.empty());
    RC_ASSERT(dual.mesh.hexes.size() == interior);
    const DualCounts counts = count_dual(k);
    RC_ASSERT(counts.hexes == interior);
    RC_ASSERT(counts.non_cubes == 0u);
    RC_ASSERT(euler_characteristic(k) == 1);
}

RC_GTEST_PROP(TopologyProperties, BoxesOfCubesAreValidWithAllHexDual, ()) {
    const Box box = random_box();
    const CellComplex k = build_box(box, *rc::gen::arbitrary<std::uint64_t>());
    RC_ASSERT(k.n_cells() == static_cast<std::size_t>(box.n[0] * box.n[1] * box.n[2]));
    check_box_properties(k, expected_interior(box));
}

// Exact orientation test: 8 x centroids, Jacobian sign at each hex corner.
bool hexes_positive(const CellComplex& k, const HexMesh& mesh) {
    static constexpr int kNbr[8][3] = {{1, 3, 4}, {2, 0, 5}, {3, 1, 6}, {0, 2, 7},
                                       {7, 5, 0}, {4, 6, 1}, {5, 7, 2}, {6, 4, 3}};
    auto centroid8 = [&](CellHandle c) {
        std::vector<VertexHandle> vs;
        for (HalfFaceHandle h : k.cell_halffaces(c))
            for (VertexHandle v : k.face_vertices(h.face())) vs.push_back(v);
        std::sort(vs.begin(), vs.end());
        vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
        LatticePoint s;
        for (VertexHandle v : vs) s = s + k.position(v);
        return s;  // all cells are cubes: 8 vertices
    };
    for (const auto& hex : mesh.hexes)
        for (int i = 0; i < 8; ++i) {
            const LatticePoint p = centroid8(hex[i]);
            const LatticePoint a = centroid8(hex[kNbr[i][0]]) - p, b = centroid8(hex[kNbr[i][1]]) - p,
                               c = centroid8(hex[kNbr[i][2]]) - p;
            const std::int64_t d = a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
            if (d <= 0) return false;
        }
    return true;
}

RC_GTEST_PROP(TopologyProperties, SymmetriesPreserveValidityAndHistograms, ()) {
    const Box box = random_box();
    const CellComplex k = build_box(box, 1);
    const CubeSymmetry s = CubeSymmetry::from_index(*rc::gen::inRange(0, CubeSymmetry::kOrder));
    const LatticePoint t{*rc::gen::inRange(-1000, 1001), *rc::gen::inRange(-1000, 1001), *rc::gen::inRange(-1000, 1001)};
    const CellComplex moved = transform(k, s, t);
    RC_ASSERT(moved.n_vertices() == k.n_vertices());
    RC_ASSERT(moved.n_edges() == k.n_edges());
    check_box_properties(moved, expected_interior(box));
    RC_ASSERT(face_size_histogram(moved) == face_size_histogram(k));
    RC_ASSERT(interior_dual_edge_valence_histogram(moved) == interior_dual_edge_valence_histogram(k));
    RC_ASSERT(hexes_positive(moved, interior_dual(moved).mesh));
}

TEST(TopologyProperties, ReflectionFlipsHalfFaces) {
    const CellComplex k = make_box({0, 0, 0}, {2, 2, 2});
    const CubeSymmetry mirror({0, 1, 2}, {-1, 1, 1});
    ASSERT_FALSE(mirror.is_rotation());
    const CellComplex m = transform(k, mirror, {5, 0, 0});
    for (std::size_t c = 0; c < k.n_cells(); ++c)
        for (std::size_t i = 0; i < k.cell_halffaces(CellHandle(c)).size(); ++i)
            EXPECT_EQ(m.cell_halffaces(CellHandle(c))[i], k.cell_halffaces(CellHandle(c))[i].opposite());
    EXPECT_TRUE(validate(m).ok());
    EXPECT_TRUE(hexes_positive(m, interior_dual(m).mesh));
    // Mirrored positions without the flip: combinatorially still valid, but every cell is
    // inward-oriented, which shows up as inverted dual hexes.
    std::vector<LatticePoint> mirrored;
    for (const LatticePoint& p : k.positions()) mirrored.push_back(mirror.apply(p));
    const CellComplex unflipped(mirrored, k.face_offsets(), k.face_loops(), k.cell_offsets(), k.all_cell_halffaces());
    EXPECT_TRUE(validate(unflipped).ok());
    EXPECT_FALSE(hexes_positive(unflipped, interior_dual(unflipped).mesh));
    const CellComplex rotated = transform(k, CubeSymmetry({1, 0, 2}, {-1, 1, 1}), {});
    EXPECT_TRUE(hexes_positive(rotated, interior_dual(rotated).mesh));
}

}  // namespace
}  // namespace dualhex
