// The audit's checks on hand-made meshes written to files and read back: good meshes pass
// every check, and each defect fails exactly the check that names it, located by cell id,
// file line, point ids and coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "dualhex/audit/audit.hpp"
#include "dualhex/audit/read_mesh.hpp"
#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "test_audit_fixture.hpp"
#include "test_geometry_hex_block.hpp"

namespace {

using namespace dualhex::audit;
using dualhex::geometry::HexMesh;
using Coordinates = std::array<double, 3>;

class AuditChecks : public audit_test::TempDir {
protected:
    AuditReport audit_hex_mesh(const HexMesh& m, const std::string& name = "m.vtk", AuditOptions options = {}) {
        dualhex::geometry::write_hex_mesh(path(name), m);
        return audit_mesh(read_mesh(path(name)), options);
    }
    AuditReport audit_cubes(const std::vector<std::vector<audit_test::Cube>>& groups) {
        dualhex::geometry::write_complex_vtk(path("poly.vtk"), audit_test::complex_of_cube_groups(groups));
        return audit_mesh(read_mesh(path("poly.vtk")));
    }
};

const CheckResult& check(const AuditReport& r, const std::string& name) {
    for (const CheckResult& c : r.checks)
        if (c.name == name) return c;
    throw std::runtime_error("no check " + name);
}

// The names of the failed checks.
std::set<std::string> failed(const AuditReport& r) {
    std::set<std::string> s;
    for (const CheckResult& c : r.checks)
        if (!c.passed()) s.insert(c.name);
    return s;
}

// The line of hex `h` in a file of write_vtk_legacy: 4 header lines, POINTS, the points, CELLS.
int vtk_cell_line(const HexMesh& m, std::size_t h) { return static_cast<int>(4 + 1 + m.points.size() + 1 + 1 + h); }

TEST_F(AuditChecks, UniformBlockPassesEveryHexCheck) {
    const auto m = geometry_test::hex_block(3, 2, 2).mesh;
    const AuditReport r = audit_hex_mesh(m);
    EXPECT_EQ(r.mode, "hex");
    EXPECT_TRUE(r.ok()) << r.text();
    EXPECT_EQ(r.checks.size(), 8U);
    EXPECT_EQ(check(r, "not-inverted").checked, 12U);
    EXPECT_EQ(check(r, "boundary-edges").checked, r.statistics["boundary_edges"].get<std::size_t>());
    // interior edges: x (3*1*1) + y (2*2*1) + z (2*1*2), each in 4 hexes
    EXPECT_EQ(r.statistics["interior_edge_valences"], (nlohmann::json{{"4", 11}}));
    EXPECT_EQ(r.statistics["hex_components"], (nlohmann::json{12}));
    EXPECT_EQ(r.statistics["boundary_components"][0]["euler"], 2);
    EXPECT_EQ(r.statistics["scaled_jacobian_histogram"], (nlohmann::json{{"[0.8,1]", 12}}));
    // the same through MEDIT and VTU
    for (const std::string name : {"m.mesh", "m.vtu"}) EXPECT_TRUE(audit_hex_mesh(m, name).ok()) << name;
}

TEST_F(AuditChecks, RepeatedVertexIsLocated) {
    auto m = geometry_test::hex_block(2, 1, 1).mesh;
    m.hexes[1][6] = m.hexes[1][5];
    const AuditReport r = audit_hex_mesh(m);
    EXPECT_EQ(failed(r), (std::set<std::string>{"distinct-vertices"})) << r.text();
    const CheckResult& c = check(r, "distinct-vertices");
    ASSERT_EQ(c.violations, 1U);
    EXPECT_EQ(c.first[0].cell, 1);
    EXPECT_EQ(c.first[0].line, vtk_cell_line(m, 1));
    EXPECT_NE(r.text().find("cell 1 (line " + std::to_string(vtk_cell_line(m, 1)) + ")"), std::string::npos) << r.text();
}

TEST_F(AuditChecks, NonHexCellIsLocated) {
    const auto m = geometry_test::hex_block(1, 1, 1).mesh;
    std::vector<Coordinates> pts;
    for (const auto& p : m.points) pts.push_back({p.x(), p.y(), p.z()});
    pts.push_back({0, 0, 2});
    std::vector<audit_test::VtkCell> cells{{12, {m.hexes[0].begin(), m.hexes[0].end()}}, {10, {4, 5, 7, 8}}};
    const AuditReport r = audit_mesh(read_mesh(write("mixed.vtk", audit_test::vtk_text(pts, cells))));
    const CheckResult& c = check(r, "hexahedra");
    ASSERT_EQ(c.violations, 1U) << r.text();
    EXPECT_EQ(c.first[0].cell, 1);
    EXPECT_NE(c.first[0].what.find("tetra"), std::string::npos);
    EXPECT_FALSE(r.ok());
}

// A big hex below a 2x2x1 block of small ones, sharing only the 4 corners of its top face:
// no combinatorial face defect, but the boundary is pinched at exactly those corners.
TEST_F(AuditChecks, NonConformingJunctionIsLocatedAtItsCorners) {
    auto m = geometry_test::hex_block(2, 2, 1).mesh;  // [0,2]^2 x [0,1]
    const int corner[4] = {0, 2, 8, 6};                // (0,0,0), (2,0,0), (2,2,0), (0,2,0)
    std::array<int, 8> big{};
    for (int i = 0; i < 4; ++i) {
        big[static_cast<std::size_t>(i + 4)] = corner[i];
        big[static_cast<std::size_t>(i)] = static_cast<int>(m.points.size());
        m.points.push_back(m.points[static_cast<std::size_t>(corner[i])] - Eigen::Vector3d(0, 0, 2));
    }
    m.hexes.push_back(big);
    const AuditReport r = audit_hex_mesh(m);
    EXPECT_TRUE(check(r, "conforming-faces").passed());
    const CheckResult& c = check(r, "boundary-vertices");
    ASSERT_EQ(c.violations, 4U) << r.text();
    std::set<std::int64_t> located;
    for (const Violation& v : c.first) located.insert(v.points.at(0));
    EXPECT_EQ(located, (std::set<std::int64_t>{0, 2, 6, 8}));
    EXPECT_FALSE(r.ok());
}

TEST_F(AuditChecks, HexesSharingOnlyAnEdgeGiveANonManifoldEdge) {
    const auto a = geometry_test::hex_block(2, 2, 1).mesh;
    HexMesh m = a;  // keep cells (0,0) and (1,1) only: they share the edge x = y = 1
    m.hexes = {a.hexes[0], a.hexes[3]};
    const AuditReport r = audit_hex_mesh(m);
    const CheckResult& c = check(r, "boundary-edges");
    ASSERT_EQ(c.violations, 1U) << r.text();
    EXPECT_EQ(c.first[0].coordinates, (std::vector<Coordinates>{{1, 1, 0}, {1, 1, 1}}));
    EXPECT_NE(c.first[0].what.find("4 boundary quads"), std::string::npos);
    EXPECT_FALSE(check(r, "connected").passed());  // they share no face either
}

TEST_F(AuditChecks, TwoComponentsAreEachLocated) {
    const auto a = geometry_test::hex_block(3, 1, 1).mesh;
    HexMesh m = a;
    m.hexes = {a.hexes[0], a.hexes[2]};  // x in [0,1] and [2,3]
    const AuditReport r = audit_hex_mesh(m);
    EXPECT_EQ(failed(r), (std::set<std::string>{"connected"})) << r.text();
    const CheckResult& c = check(r, "connected");
    ASSERT_EQ(c.violations, 2U);
    EXPECT_EQ(c.first[0].cell + c.first[1].cell, 1);  // cells 0 and 1
    EXPECT_EQ(r.statistics["hex_components"], (nlohmann::json{1, 1}));
    EXPECT_EQ(r.statistics["boundary_components"].size(), 2U);
}

TEST_F(AuditChecks, InvertedHexIsLocated) {
    auto m = geometry_test::hex_block(2, 1, 1).mesh;
    m.points[2] = Eigen::Vector3d(0.5, 0, 0);  // hex 1's corner (2,0,0) pushed through its face x = 1
    const AuditReport r = audit_hex_mesh(m);
    EXPECT_EQ(failed(r), (std::set<std::string>{"not-inverted"})) << r.text();
    const CheckResult& c = check(r, "not-inverted");
    ASSERT_EQ(c.violations, 1U);
    EXPECT_EQ(c.first[0].cell, 1);
}

TEST_F(AuditChecks, DuplicateHexIsAFaceDefect) {
    auto m = geometry_test::hex_block(1, 1, 1).mesh;
    m.hexes.push_back(m.hexes[0]);
    const AuditReport r = audit_hex_mesh(m);
    EXPECT_EQ(check(r, "conforming-faces").violations, 6U) << r.text();
}

TEST_F(AuditChecks, MaxListedBoundsTheListNotTheCount) {
    auto m = geometry_test::hex_block(4, 1, 1).mesh;
    for (auto& h : m.hexes) h[7] = h[6];
    AuditOptions o;
    o.max_listed = 2;
    const AuditReport r = audit_hex_mesh(m, "m.vtk", o);
    EXPECT_EQ(check(r, "distinct-vertices").violations, 4U);
    EXPECT_EQ(check(r, "distinct-vertices").first.size(), 2U);
    EXPECT_NE(r.text().find("... 2 more"), std::string::npos);
}

TEST_F(AuditChecks, EmptyMeshFailsInBothModes) {
    const std::string p = write("empty.vtk", audit_test::vtk_text({{0, 0, 0}}, {}));
    EXPECT_FALSE(check(audit_mesh(read_mesh(p)), "hexahedra").passed());
    AuditOptions o;
    o.mode = AuditMode::Polyhedral;
    EXPECT_FALSE(audit_mesh(read_mesh(p), o).ok());
}

TEST_F(AuditChecks, CubeComplexPassesEveryPolyhedralCheck) {
    const AuditReport r = audit_cubes(audit_test::unit_cubes(3));
    EXPECT_EQ(r.mode, "polyhedral");
    EXPECT_TRUE(r.ok()) << r.text();
    EXPECT_EQ(r.checks.size(), 6U);
    EXPECT_EQ(r.statistics["interior_vertices"], 8);
    EXPECT_EQ(r.statistics["interior_dual_edge_valences"], (nlohmann::json{{"4", 6}}));
    EXPECT_EQ(r.statistics["checked"]["interior_vertices"], 8);
    EXPECT_EQ(check(r, "vertex-valence").checked, 8U);  // a PASS says over how many
    EXPECT_EQ(check(r, "cells-closed").checked, 27U);
}

// The 4 cubes around the +x edge of the centre of [0,2]^3 as one cell: that edge is gone.
TEST_F(AuditChecks, InteriorVertexOfValenceFiveIsLocated) {
    auto groups = audit_test::unit_cubes(2);
    audit_test::merge(groups, {{{1, 0, 0}}, {{1, 1, 0}}, {{1, 0, 1}}, {{1, 1, 1}}});
    const AuditReport r = audit_cubes(groups);
    const CheckResult& c = check(r, "vertex-valence");
    ASSERT_GE(c.violations, 1U) << r.text();
    EXPECT_EQ(c.first[0].coordinates, (std::vector<Coordinates>{{1, 1, 1}})) << r.text();
    EXPECT_NE(c.first[0].what.find("VertexValence"), std::string::npos) << c.first[0].what;
    EXPECT_TRUE(check(r, "cells-closed").passed());
    EXPECT_TRUE(check(r, "conforming-faces").passed());
}

// Two of the 4 cubes around the interior edge (1,1,1)-(1,1,2) of [0,3]^3 as one cell.
TEST_F(AuditChecks, InteriorEdgeOfValenceThreeIsLocated) {
    auto groups = audit_test::unit_cubes(3);
    audit_test::merge(groups, {{{0, 0, 1}}, {{1, 0, 1}}});
    const AuditReport r = audit_cubes(groups);
    const CheckResult& c = check(r, "edge-valence");
    ASSERT_GE(c.violations, 1U) << r.text();
    bool found = false;
    for (const Violation& v : c.first)
        found = found || (v.coordinates == std::vector<Coordinates>{{1, 1, 1}, {1, 1, 2}} && v.what.find("3") != std::string::npos);
    EXPECT_TRUE(found) << r.text();
    EXPECT_TRUE(check(r, "cells-closed").passed());
}

TEST_F(AuditChecks, MisorientedPolyhedronFaceIsReported) {
    auto k = audit_test::complex_of_cube_groups(audit_test::unit_cubes(2));
    dualhex::geometry::write_complex_vtk(path("poly.vtk"), k);
    MeshFile f = read_mesh(path("poly.vtk"));
    std::reverse(f.cells[0].faces[0].begin(), f.cells[0].faces[0].end());
    const AuditReport r = audit_mesh(f);
    EXPECT_FALSE(check(r, "cells-closed").passed()) << r.text();
    EXPECT_EQ(check(r, "cells-closed").first[0].cell, 0);
}

}  // namespace
