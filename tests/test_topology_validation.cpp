// Mutation tests for validate(): each broken complex must be rejected with the specific
// violation kind naming the right entity; the unbroken ones must report nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include <tbb/global_control.h>

#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/incidence.hpp"
#include "dualhex/topology/primitives.hpp"
#include "dualhex/topology/validation.hpp"

namespace dualhex {
namespace {

using Loop = std::vector<LatticePoint>;
using CellLoops = std::vector<Loop>;

// Unit cubes of the box [0,nx]x[0,ny]x[0,nz] (x slowest), as outward loops.
std::vector<CellLoops> box_cells(int nx, int ny, int nz) {
    std::vector<CellLoops> cells;
    for (int i = 0; i < nx; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nz; ++k) cells.push_back(cube_loops({i, j, k}));
    return cells;
}

std::size_t cube_index(int i, int j, int k, int ny, int nz) { return static_cast<std::size_t>((i * ny + j) * nz + k); }

// The boundary of the union of several cells: loops shared by two of them cancel.
CellLoops merge(const std::vector<CellLoops>& parts) {
    std::vector<std::pair<Loop, Loop>> keyed;  // (sorted vertices, loop)
    for (const auto& part : parts)
        for (const auto& loop : part) {
            Loop key = loop;
            std::sort(key.begin(), key.end());
            keyed.emplace_back(key, loop);
        }
    CellLoops out;
    for (const auto& [key, loop] : keyed)
        if (std::count_if(keyed.begin(), keyed.end(), [&](const auto& kv) { return kv.first == key; }) == 1)
            out.push_back(loop);
    return out;
}

CellComplex build(const std::vector<CellLoops>& cells) {
    ComplexBuilder b;
    for (const auto& c : cells) b.add_cell_from_loops(c);
    return b.build();
}

VertexHandle vertex_at(const CellComplex& k, LatticePoint p) {
    for (std::size_t i = 0; i < k.n_vertices(); ++i)
        if (k.position(VertexHandle(i)) == p) return VertexHandle(i);
    return {};
}

EdgeHandle edge_at(const CellComplex& k, LatticePoint a, LatticePoint b) {
    return Incidence(k).find_edge(vertex_at(k, a), vertex_at(k, b));
}

std::string dump(const ValidationReport& r, const CellComplex& k) {
    std::ostringstream os;
    r.print(os, k);
    return os.str();
}

// Splits the unit cube at (x, y, z) into two triangular prisms by the plane through
// its vertical edges at (x, y) and (x+1, y+1).
std::vector<CellLoops> split_into_prisms(int x, int y, int z) {
    auto prism = [&](std::vector<std::array<int, 2>> tri) {  // counter-clockwise seen from +z
        CellLoops loops;
        auto p = [&](std::array<int, 2> q, int dz) { return LatticePoint{x + q[0], y + q[1], z + dz}; };
        loops.push_back({p(tri[0], 0), p(tri[2], 0), p(tri[1], 0)});
        loops.push_back({p(tri[0], 1), p(tri[1], 1), p(tri[2], 1)});
        for (int i = 0; i < 3; ++i) {
            const auto a = tri[static_cast<std::size_t>(i)], b = tri[static_cast<std::size_t>((i + 1) % 3)];
            loops.push_back({p(a, 0), p(b, 0), p(b, 1), p(a, 1)});
        }
        return loops;
    };
    return {prism({{{0, 0}, {1, 0}, {1, 1}}}), prism({{{0, 0}, {1, 1}, {0, 1}}})};
}

TEST(TopologyValidation, ValidBlocksReportNothing) {
    for (int n = 1; n <= 3; ++n) {
        const CellComplex k = build(box_cells(n, n, n));
        const ValidationReport r = validate(k);
        EXPECT_TRUE(r.ok()) << dump(r, k);
    }
    // A stack of two cubes.
    auto cells = box_cells(1, 1, 2);
    const CellComplex k = build(cells);
    EXPECT_TRUE(validate(k).ok());
}

TEST(TopologyValidation, DroppedFaceOpensTheCell) {
    auto cells = box_cells(2, 1, 1);
    cells[0].erase(cells[0].begin() + 1);  // its x = 1 face, shared with cell 1
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::CellOpenEdge, CellHandle(0))) << dump(r, k);
    EXPECT_TRUE(r.has(ViolationKind::CellNotSphere, CellHandle(0)));
    EXPECT_FALSE(r.has(ViolationKind::CellOpenEdge, CellHandle(1)));
}

TEST(TopologyValidation, ReversedFaceBreaksOrientation) {
    auto cells = box_cells(2, 1, 1);
    std::reverse(cells[0][1].begin(), cells[0][1].end());
    const CellComplex k = build(cells);
    const FaceHandle shared = k.cell_halffaces(CellHandle(0))[1].face();
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::CellInconsistentOrientation, CellHandle(0))) << dump(r, k);
    EXPECT_TRUE(r.has(ViolationKind::FaceSameOrientation, shared));
    EXPECT_EQ(r.count(ViolationKind::CellInconsistentOrientation), 4u);  // the reversed quad's 4 edges
}

TEST(TopologyValidation, DuplicatedCell) {
    auto cells = box_cells(2, 1, 1);
    cells.push_back(cells[0]);
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::DuplicateCell, CellHandle(2))) << dump(r, k);
    EXPECT_EQ(r.count(ViolationKind::DuplicateCell), 1u);
    EXPECT_TRUE(r.has(ViolationKind::FaceOvershared, k.cell_halffaces(CellHandle(0))[1].face()));
}

TEST(TopologyValidation, FaceSharedByThreeCells) {
    auto cells = box_cells(1, 1, 2);  // z in [0,1] and [1,2], sharing the face z = 1
    // A pyramid on that face (apex off the lattice box: combinatorics only).
    const Loop base{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}};  // normal -z, outward for the pyramid
    const LatticePoint apex{0, 0, 3};
    CellLoops pyramid{base};
    for (std::size_t i = 0; i < 4; ++i) pyramid.push_back({base[(i + 1) % 4], base[i], apex});
    cells.push_back(pyramid);
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    const FaceHandle shared = k.cell_halffaces(CellHandle(2))[0].face();
    EXPECT_TRUE(r.has(ViolationKind::FaceOvershared, shared)) << dump(r, k);
    EXPECT_EQ(r.count(ViolationKind::FaceOvershared), 1u);
    for (auto kind : {ViolationKind::CellOpenEdge, ViolationKind::CellInconsistentOrientation, ViolationKind::CellNotSphere})
        EXPECT_FALSE(r.has(kind, CellHandle(2)));  // the pyramid itself is fine
}

TEST(TopologyValidation, FaceWithRepeatedVertex) {
    auto cells = box_cells(1, 1, 1);
    Loop& top = cells[0][5];
    top.insert(top.begin() + 2, top[0]);  // p0 p1 p0 p2 p3
    const CellComplex k = build(cells);
    const FaceHandle f = k.cell_halffaces(CellHandle(0))[5].face();
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::FaceRepeatedVertex, f)) << dump(r, k);
    EXPECT_FALSE(r.has(ViolationKind::FaceTooFewVertices, f));
}

TEST(TopologyValidation, DegenerateFace) {
    ComplexBuilder b;
    const VertexHandle a = b.add_vertex({0, 0, 0}), c = b.add_vertex({1, 0, 0});
    const HalfFaceHandle h = b.add_face({a, c});
    const CellComplex k = b.build();
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::FaceTooFewVertices, h.face())) << dump(r, k);
    EXPECT_TRUE(r.has(ViolationKind::FaceUnused, h.face()));
}

TEST(TopologyValidation, FacesGluedWithTheSameOrientation) {
    auto cells = box_cells(2, 1, 1);
    for (Loop& loop : cells[1]) std::reverse(loop.begin(), loop.end());  // cell 1 inward, but consistent
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    const FaceHandle shared = k.cell_halffaces(CellHandle(0))[1].face();
    EXPECT_TRUE(r.has(ViolationKind::FaceSameOrientation, shared)) << dump(r, k);
    EXPECT_EQ(r.violations.size(), 1u) << dump(r, k);
}

TEST(TopologyValidation, SplitColumnGivesValence7AndFiveCellEdges) {
    auto cells = box_cells(3, 3, 3);
    for (int z = 2; z >= 0; --z) {
        const std::size_t at = cube_index(1, 1, z, 3, 3);
        cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(at));
        const auto prisms = split_into_prisms(1, 1, z);
        cells.insert(cells.end(), prisms.begin(), prisms.end());
    }
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    for (LatticePoint p : {LatticePoint{1, 1, 1}, LatticePoint{2, 2, 1}, LatticePoint{1, 1, 2}, LatticePoint{2, 2, 2}}) {
        EXPECT_TRUE(r.has(ViolationKind::VertexValence, vertex_at(k, p))) << p << dump(r, k);
        EXPECT_TRUE(r.has(ViolationKind::VertexLinkNotOctahedron, vertex_at(k, p)));
        EXPECT_TRUE(r.has(ViolationKind::DualCellNotCube, vertex_at(k, p)));
    }
    EXPECT_FALSE(r.has(ViolationKind::VertexValence, vertex_at(k, {2, 1, 1})));
    EXPECT_EQ(r.count(ViolationKind::VertexValence), 4u) << dump(r, k);
    const EdgeHandle column = edge_at(k, {1, 1, 1}, {1, 1, 2});
    ASSERT_TRUE(column.valid());
    EXPECT_TRUE(r.has(ViolationKind::EdgeCellCount, column));
    EXPECT_EQ(Incidence(k).edge_cells(column).size(), 5u);
    EXPECT_FALSE(r.has(ViolationKind::EdgeCellsNotCycle, column));  // 5 cells, but one cycle
    for (auto kind : {ViolationKind::CellOpenEdge, ViolationKind::FaceOvershared, ViolationKind::FaceSameOrientation})
        EXPECT_EQ(r.count(kind), 0u);
}

TEST(TopologyValidation, MergedPairGivesThreeCellEdge) {
    auto cells = box_cells(3, 3, 3);
    const std::size_t a = cube_index(0, 1, 1, 3, 3), b = cube_index(1, 1, 1, 3, 3);
    const CellLoops merged = merge({cells[a], cells[b]});
    ASSERT_EQ(merged.size(), 10u);
    cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(b));
    cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(a));
    cells.push_back(merged);
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    const EdgeHandle e = edge_at(k, {1, 1, 1}, {1, 1, 2});
    ASSERT_TRUE(e.valid());
    EXPECT_TRUE(r.has(ViolationKind::EdgeCellCount, e)) << dump(r, k);
    EXPECT_EQ(Incidence(k).edge_cells(e).size(), 3u);
    EXPECT_TRUE(r.has(ViolationKind::DualCellNotCube, vertex_at(k, {1, 1, 1})));
    EXPECT_TRUE(r.has(ViolationKind::VertexLinkNotOctahedron, vertex_at(k, {1, 1, 1})));
    EXPECT_FALSE(r.has(ViolationKind::VertexValence, vertex_at(k, {1, 1, 1})));  // still 6 edges
    EXPECT_FALSE(r.has(ViolationKind::CellNotSphere, CellHandle(k.n_cells() - 1)));
}

TEST(TopologyValidation, MergedQuadrupleGivesValence5) {
    auto cells = box_cells(3, 3, 3);
    std::vector<std::size_t> ids{cube_index(0, 0, 1, 3, 3), cube_index(0, 1, 1, 3, 3), cube_index(1, 0, 1, 3, 3),
                                 cube_index(1, 1, 1, 3, 3)};
    std::vector<CellLoops> parts;
    for (std::size_t id : ids) parts.push_back(cells[id]);
    const CellLoops merged = merge(parts);
    for (auto it = ids.rbegin(); it != ids.rend(); ++it) cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(*it));
    cells.push_back(merged);
    const CellComplex k = build(cells);
    const ValidationReport r = validate(k);
    const VertexHandle v = vertex_at(k, {1, 1, 1});
    EXPECT_TRUE(r.has(ViolationKind::VertexValence, v)) << dump(r, k);
    EXPECT_EQ(Incidence(k).vertex_edges(v).size(), 5u);
    EXPECT_FALSE(edge_at(k, {1, 1, 1}, {1, 1, 2}).valid());
    EXPECT_TRUE(r.has(ViolationKind::DualCellNotCube, v));
}

TEST(TopologyValidation, TorusCell) {
    std::vector<CellLoops> ring;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (i != 1 || j != 1) ring.push_back(cube_loops({i, j, 0}));
    const CellComplex k = build({merge(ring)});
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::CellNotSphere, CellHandle(0))) << dump(r, k);
    EXPECT_FALSE(r.has(ViolationKind::CellDisconnected, CellHandle(0)));
    EXPECT_FALSE(r.has(ViolationKind::CellOpenEdge, CellHandle(0)));
    EXPECT_NE(r.violations.front().message.find("= 0"), std::string::npos);
}

TEST(TopologyValidation, TwoSpheresInOneCell) {
    CellLoops two = cube_loops({0, 0, 0});
    for (const Loop& l : cube_loops({5, 0, 0})) two.push_back(l);
    const CellComplex k = build({two});
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::CellDisconnected, CellHandle(0))) << dump(r, k);
    EXPECT_TRUE(r.has(ViolationKind::CellNotSphere, CellHandle(0)));
}

TEST(TopologyValidation, PinchedCellVertex) {
    // Two cubes touching at one vertex, as a single cell: closed and oriented, but the
    // vertex (1,1,1) has two cycles of faces around it.
    CellLoops two = cube_loops({0, 0, 0});
    for (const Loop& l : cube_loops({1, 1, 1})) two.push_back(l);
    const CellComplex k = build({two});
    const ValidationReport r = validate(k);
    EXPECT_TRUE(r.has(ViolationKind::CellNonManifoldVertex, CellHandle(0))) << dump(r, k);
    EXPECT_TRUE(r.has(ViolationKind::CellDisconnected, CellHandle(0)));
}

TEST(TopologyValidation, FilterRestrictsInteriorChecks) {
    auto cells = box_cells(3, 3, 3);
    const std::size_t a = cube_index(0, 1, 1, 3, 3), b = cube_index(1, 1, 1, 3, 3);
    const CellLoops merged = merge({cells[a], cells[b]});
    cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(b));
    cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(a));
    cells.push_back(merged);
    const CellComplex k = build(cells);
    ValidationOptions options;
    options.interior_filter = [&](VertexHandle v) { return k.position(v).x >= 2; };  // away from the merge
    const ValidationReport r = validate(k, options);
    EXPECT_TRUE(r.ok()) << dump(r, k);
    EXPECT_EQ(r.checked_vertices, 4u);
    EXPECT_GT(r.checked_edges, 0u);
}

TEST(TopologyValidation, InteriorChecksCanBeSwitchedOff) {
    auto cells = box_cells(3, 3, 3);
    const std::size_t a = cube_index(0, 1, 1, 3, 3), b = cube_index(1, 1, 1, 3, 3);
    const CellLoops merged = merge({cells[a], cells[b]});
    cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(b));
    cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(a));
    cells.push_back(merged);
    const CellComplex k = build(cells);
    ValidationOptions options;
    options.check_interior = false;
    const ValidationReport r = validate(k, options);
    EXPECT_TRUE(r.ok()) << dump(r, k);  // (1) and (2) hold; only valences are off
    EXPECT_EQ(r.checked_vertices, 0u);
    EXPECT_FALSE(validate(k).ok());
}

TEST(TopologyValidation, ReportPrintsPositions) {
    auto cells = box_cells(2, 1, 1);
    cells.push_back(cells[0]);
    const CellComplex k = build(cells);
    const std::string text = dump(validate(k), k);
    EXPECT_NE(text.find("INVALID"), std::string::npos);
    EXPECT_NE(text.find("DuplicateCell"), std::string::npos);
    EXPECT_NE(text.find("(1,0,0)"), std::string::npos);
}

// validate() runs in parallel over fixed blocks of 4096 ids on a large complex: its report
// must be the serial loop's, entry for entry, at any thread count. An 18^3 block (6,859
// vertices: two blocks of vertex ids) with two columns split into prisms, far apart in id
// order, so that violations come from both blocks.
TEST(TopologyValidation, ALargeComplexGetsTheSerialReportAtAnyThreadCount) {
    constexpr int n = 18;
    auto cells = box_cells(n, n, n);
    std::vector<std::size_t> erased;
    for (int column : {2, 15})
        for (int z = 0; z < n; ++z) {
            erased.push_back(cube_index(column, column, z, n, n));
            const auto prisms = split_into_prisms(column, column, z);
            cells.insert(cells.end(), prisms.begin(), prisms.end());
        }
    std::sort(erased.rbegin(), erased.rend());
    for (std::size_t at : erased) cells.erase(cells.begin() + static_cast<std::ptrdiff_t>(at));
    const CellComplex k = build(cells);
    ASSERT_GT(k.n_vertices(), 4096u);
    const auto run = [&](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
        return validate(k);
    };
    const ValidationReport one = run(1), four = run(4);
    ASSERT_EQ(one.violations.size(), four.violations.size());
    for (std::size_t i = 0; i < one.violations.size(); ++i) {
        const Violation &a = one.violations[i], &b = four.violations[i];
        EXPECT_TRUE(a.kind == b.kind && a.vertex == b.vertex && a.edge == b.edge && a.face == b.face &&
                    a.cell == b.cell && a.message == b.message)
            << i;
    }
    EXPECT_EQ(one.per_kind, four.per_kind);
    EXPECT_EQ(one.checked_vertices, static_cast<std::size_t>((n - 1) * (n - 1) * (n - 1)));
    EXPECT_EQ(four.checked_vertices, one.checked_vertices);
    EXPECT_EQ(four.checked_edges, one.checked_edges);
    // The serial order: interior vertices by id (all their violations before the edges'),
    // from both blocks.
    std::vector<std::size_t> vertex_ids;
    for (const Violation& v : four.violations)
        if (v.vertex.valid()) vertex_ids.push_back(v.vertex.index());
    ASSERT_FALSE(vertex_ids.empty());
    EXPECT_TRUE(std::is_sorted(vertex_ids.begin(), vertex_ids.end()));
    EXPECT_LT(vertex_ids.front(), 4096u);
    EXPECT_GE(vertex_ids.back(), 4096u);
    for (int column : {2, 15})
        EXPECT_TRUE(four.has(ViolationKind::VertexValence, vertex_at(k, {column, column, n / 2}))) << column;
}

}  // namespace
}  // namespace dualhex
