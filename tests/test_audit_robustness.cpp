// The readers on damaged files: truncations of a valid file (VTK legacy, VTU, MEDIT,
// hex and polyhedral) and random byte mutations either read or throw InputError naming the
// file, never another exception, a crash or a hang; whatever is read has every id in range.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dualhex/audit/audit.hpp"
#include "dualhex/audit/read_mesh.hpp"
#include "dualhex/geometry/complex_output.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/grid/input_error.hpp"
#include "test_audit_fixture.hpp"
#include "test_geometry_hex_block.hpp"

namespace {

using namespace dualhex::audit;
namespace fs = std::filesystem;

fs::path scratch() {
    const fs::path d = fs::temp_directory_path() / ("dualhex_audit_robustness_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

std::string read_bytes(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Reads `text` as a file with extension `ext`: true if read (then audited), false on InputError.
bool read_or_refuse(const std::string& ext, const std::string& text) {
    const std::string p = (scratch() / ("damaged" + ext)).string();
    std::ofstream(p, std::ios::binary | std::ios::trunc) << text;
    try {
        const MeshFile f = read_mesh(p);
        for (const MeshCell& c : f.cells) {
            for (auto v : c.points) EXPECT_TRUE(v >= 0 && static_cast<std::size_t>(v) < f.points.size());
            for (const auto& face : c.faces)
                for (auto v : face) EXPECT_TRUE(v >= 0 && static_cast<std::size_t>(v) < f.points.size());
        }
        (void)audit_mesh(f);  // whatever reads must audit without throwing
        return true;
    } catch (const dualhex::InputError& e) {
        EXPECT_EQ(e.file(), p);
        return false;
    }
}

// Valid sample files, by extension.
std::vector<std::pair<std::string, std::string>> samples() {
    const fs::path d = scratch();
    const auto m = geometry_test::hex_block(2, 1, 1).mesh;
    std::vector<std::pair<std::string, std::string>> out;
    for (const std::string ext : {".vtk", ".vtu", ".mesh"}) {
        const std::string p = (d / ("sample" + ext)).string();
        dualhex::geometry::write_hex_mesh(p, m, true);
        out.emplace_back(ext, read_bytes(p));
    }
    const std::string poly = (d / "poly.vtk").string();
    dualhex::geometry::write_complex_vtk(poly, audit_test::complex_of_cube_groups(audit_test::unit_cubes(2)), {}, true);
    out.emplace_back(".vtk", read_bytes(poly));
    return out;
}

TEST(AuditRobustness, TruncationsReadOrAreRefused) {
    for (const auto& [ext, text] : samples()) {
        std::size_t refused = 0, tried = 0;
        // every 5th prefix, and each of the last 64 (where the cell types end)
        for (std::size_t n = 0; n < text.size(); n += (n + 64 < text.size() ? 5 : 1), ++tried)
            refused += read_or_refuse(ext, text.substr(0, n)) ? 0 : 1;
        EXPECT_GT(refused, tried / 2) << ext;  // most prefixes lack the cells
        EXPECT_TRUE(read_or_refuse(ext, text)) << ext;
    }
}

RC_GTEST_PROP(AuditRobustness, MutatedBytesReadOrAreRefused, ()) {
    static const auto files = samples();
    const auto& [ext, original] = files[*rc::gen::inRange<std::size_t>(0, files.size())];
    std::string text = original;
    const int edits = *rc::gen::inRange(1, 6);
    for (int e = 0; e < edits; ++e) {
        const std::size_t at = *rc::gen::inRange<std::size_t>(0, text.size());
        text[at] = *rc::gen::elementOf(std::string("0123456789 -+.e\n<>\"=x9"));
    }
    read_or_refuse(ext, text);
}

struct RemoveScratch : ::testing::Environment {
    void TearDown() override { fs::remove_all(scratch()); }
};
const auto* const kRemoveScratch = ::testing::AddGlobalTestEnvironment(new RemoveScratch);

}  // namespace
