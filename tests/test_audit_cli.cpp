// `dualhex audit` run as a process: dualhex's own outputs (`dualhex install`, `dualhex mesh`)
// pass (the hex mesh's interior edge valences are the complex's face sizes); the polyhedral one certifies and the standalone checker verifies the certificate; a
// defect exits 1 with its location; a malformed file exits 3 with file:line; --certify is
// refused (exit 2, no file) for non-dyadic, out-of-bound or failing meshes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "dualhex/geometry/hex_output.hpp"
#include "run_process.hpp"
#include "test_audit_fixture.hpp"
#include "test_geometry_hex_block.hpp"

namespace {

namespace fs = std::filesystem;
using dualhex::test::ProcessResult;

class AuditCli : public audit_test::TempDir {
protected:
    ProcessResult run(const std::vector<std::string>& args, const std::string& exe = DUALHEX_EXE) const {
        return dualhex::test::run_process(exe, args, dir_);
    }
    ProcessResult audit(std::vector<std::string> args) const {
        args.insert(args.begin(), "audit");
        return run(args);
    }
};

// Level 2, with the level-1 octant at the origin refined to level 3: paired, strongly balanced.
std::string two_level_grid() {
    std::string s = "# level 2, octant (0,0,0) of level 1 refined to level 3\n";
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) {
                if (i >= 2 || j >= 2 || k >= 2) {
                    s += "2 " + std::to_string(i) + ' ' + std::to_string(j) + ' ' + std::to_string(k) + '\n';
                    continue;
                }
                for (int a = 0; a < 8; ++a)
                    s += "3 " + std::to_string(2 * i + (a & 1)) + ' ' + std::to_string(2 * j + (a >> 1 & 1)) + ' ' +
                         std::to_string(2 * k + (a >> 2)) + '\n';
            }
    return s;
}

TEST_F(AuditCli, InstallOutputsPassAndThePolyhedralOneIsCertified) {
    const std::string grid = write("g.leaves", two_level_grid());
    ASSERT_EQ(run({"install", grid, "-o", path("inst")}).rc, 0);
    const ProcessResult poly = audit({path("inst.poly.vtk"), "--certify", path("a.cert"), "--json"});
    ASSERT_EQ(poly.rc, 0) << poly.out << poly.err;
    const auto j = nlohmann::json::parse(poly.out);
    EXPECT_EQ(j["mode"], "polyhedral");
    EXPECT_TRUE(j["ok"]);
    EXPECT_EQ(j["checks"].size(), 6U);
    EXPECT_GT(j["statistics"]["interior_vertices"].get<int>(), 0);
    const ProcessResult checked = run({"--file", path("a.cert")}, DUALHEX_PROOF_CHECKER);
    EXPECT_EQ(checked.rc, 0) << checked.out << checked.err;
    EXPECT_NE(checked.out.find("VERIFIED: 1 installation"), std::string::npos) << checked.out;

    const ProcessResult hex = audit({path("inst.hex.vtk"), "--json"});
    ASSERT_EQ(hex.rc, 0) << hex.out << hex.err;
    const auto h = nlohmann::json::parse(hex.out);
    EXPECT_EQ(h["mode"], "hex");
    // Duality, across the two modes' independent code: every primal k-gon is an interior
    // edge of k hexes of the clipped dual (the clipped dual keeps the boundary).
    EXPECT_EQ(h["statistics"]["interior_edge_valences"], j["statistics"]["face_sizes"]);
}

TEST_F(AuditCli, MeshOutputsPassInEveryFormat) {
    for (const std::string ext : {".vtk", ".vtu", ".mesh"}) {
        const std::string out = path("torus" + ext);
        ASSERT_EQ(run({"mesh", "--max-depth", "4", "-o", out}).rc, 0) << ext;
        const ProcessResult r = audit({out});
        EXPECT_EQ(r.rc, 0) << r.out << r.err;
        EXPECT_NE(r.out.find("\"euler\":0"), std::string::npos) << r.out;  // the torus's boundary
    }
}

TEST_F(AuditCli, IntegralHexBlockCertifiesAsHistogram) {
    dualhex::geometry::write_vtk_legacy(path("block.vtk"), geometry_test::hex_block(2, 2, 2).mesh);
    const ProcessResult r = audit({path("block.vtk"), "--certify", path("b.cert")});
    ASSERT_EQ(r.rc, 0) << r.out << r.err;
    const ProcessResult checked = run({"--file", path("b.cert")}, DUALHEX_PROOF_CHECKER);
    EXPECT_EQ(checked.rc, 0) << checked.out << checked.err;
}

TEST_F(AuditCli, DefectExitsOneWithItsLocation) {
    auto m = geometry_test::hex_block(2, 1, 1).mesh;
    m.hexes[1][6] = m.hexes[1][5];
    dualhex::geometry::write_vtk_legacy(path("bad.vtk"), m);
    const ProcessResult r = audit({path("bad.vtk"), "--certify", path("bad.cert")});
    EXPECT_EQ(r.rc, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("FAIL distinct-vertices"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cell 1 (line 20)"), std::string::npos) << r.out;  // 4 + POINTS + 12 + CELLS + 2
    EXPECT_NE(r.err.find("not certifying"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("bad.cert")));
    const ProcessResult j = audit({path("bad.vtk"), "--json"});
    EXPECT_EQ(j.rc, 1);
    const auto json = nlohmann::json::parse(j.out);
    EXPECT_FALSE(json["ok"]);
    for (const auto& c : json["checks"])
        if (c["name"] == "distinct-vertices") {
            EXPECT_EQ(c["listed"][0]["cell"], 1);
        }
}

TEST_F(AuditCli, MalformedFileExitsThreeWithFileAndLine) {
    const std::string p = write("t.vtk", "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 double\n0 0 0\n1 x 0\n");
    const ProcessResult r = audit({p});
    EXPECT_EQ(r.rc, 3);
    EXPECT_NE(r.err.find("error: " + p + ":7: bad point coordinate 'x'"), std::string::npos) << r.err;
    EXPECT_EQ(audit({path("none.vtk")}).rc, 3);
    EXPECT_EQ(audit({}).rc, 2);
}

TEST_F(AuditCli, CertifyRefusedForNonDyadicOrHugeCoordinates) {
    dualhex::geometry::write_vtk_legacy(path("tenth.vtk"), geometry_test::hex_block(1, 1, 1, 0.1).mesh);
    ProcessResult r = audit({path("tenth.vtk"), "--certify", path("t.cert")});
    EXPECT_EQ(r.rc, 2) << r.out << r.err;
    EXPECT_NE(r.err.find("integral only once scaled by 2^55"), std::string::npos) << r.err;  // 0.1 as a double
    EXPECT_FALSE(fs::exists(path("t.cert")));
    // 2^19 is the bound: a block reaching 2^19 is certified, one reaching 2^19 + 1 is not
    const double bound = 524288.0;
    dualhex::geometry::write_vtk_legacy(path("edge.vtk"), geometry_test::hex_block(1, 1, 1, bound).mesh);
    r = audit({path("edge.vtk"), "--certify", path("e.cert")});
    EXPECT_EQ(r.rc, 0) << r.err;
    dualhex::geometry::write_vtk_legacy(path("huge.vtk"), geometry_test::hex_block(1, 1, 1, bound + 1).mesh);
    r = audit({path("huge.vtk"), "--certify", path("h.cert")});
    EXPECT_EQ(r.rc, 2) << r.err;
    EXPECT_NE(r.err.find("2^19"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("h.cert")));
    // every |x| <= 2^19, but the extent 2^19 + 2 exceeds the checker's box bound
    const double h = bound / 2 + 1;
    dualhex::geometry::write_vtk_legacy(path("wide.vtk"),
                                        geometry_test::hex_block(2, 1, 1, h, Eigen::Vector3d(-h, 0, 0)).mesh);
    r = audit({path("wide.vtk"), "--certify", path("w.cert")});
    EXPECT_EQ(r.rc, 2) << r.err;
    EXPECT_NE(r.err.find("box extent 2^19"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("w.cert")));
}

}  // namespace
