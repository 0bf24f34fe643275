// dualhex-dist under mpirun -np 1..4 (--oversubscribe): the same canonical summary (counts,
// histograms, hashes) as the serial install of the same grid, paired and balanced by the
// grid layer; on the shared grids and on random grids; the .pvtu output; bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

#include <nlohmann/json.hpp>

#include "dualhex/distributed/canonical_json.hpp"
#include "test_distributed_run.hpp"
#include "test_distributed_fixture.hpp"

namespace dualhex {
namespace {

namespace fs = std::filesystem;

using test::run_dist;
using test::Scratch;

nlohmann::json dist_json(int np, const fs::path& grid, const char* balance, const fs::path& scratch,
                         const char* outside = "coarse") {
    const auto r = run_dist(np, {grid.string(), "--balance", balance, "--outside-root", outside, "--json"}, scratch);
    EXPECT_EQ(r.rc, 0) << r.err;
    return nlohmann::json::parse(r.out);
}

// Returns the pairing rounds summed over the runs.
int expect_same_as_serial(const fs::path& grid_file, Balance b, const fs::path& scratch, std::vector<int> nps,
                          OutsideRoot outside = OutsideRoot::Coarse) {
    int rounds = 0;
    const CanonicalSummary serial = test::serial_summary(read_leaf_file(grid_file), b, outside);
    EXPECT_EQ(serial.non_cube_vertices, 0U);
    for (int np : nps) {
        const nlohmann::json doc = dist_json(np, grid_file, b == Balance::Strong ? "strong" : "weak", scratch,
                                             outside == OutsideRoot::Mirror ? "mirror" : "coarse");
        EXPECT_EQ(doc["ranks"], np);
        rounds += doc["pairing_rounds"].get<int>();
        const CanonicalSummary dist = summary_from_json(doc["summary"]);
        EXPECT_EQ(to_json(dist), to_json(serial)) << grid_file << " np " << np;
        std::uint64_t leaves = 0;
        for (const auto& r : doc["per_rank"]) leaves += r["local_leaves"].get<std::uint64_t>();
        EXPECT_EQ(leaves, serial.leaves);
        if (np > 1) {  // the partition really splits the work
            for (const auto& r : doc["per_rank"]) EXPECT_GT(r["local_leaves"].get<std::uint64_t>(), 0U);
            EXPECT_GT(doc["per_rank"][0]["ghost_leaves"].get<std::uint64_t>(), 0U);
        }
    }
    return rounds;
}

fs::path shared(const char* name) { return fs::path(DUALHEX_SHARED_DATA) / "grids" / name; }

TEST(Distributed, SharedStrongGridMatchesSerialOn1To4Ranks) {
    Scratch s("strong");
    expect_same_as_serial(shared("sphere_strong_d5.leaves"), Balance::Strong, s.dir, {1, 2, 3, 4});
}

TEST(Distributed, SharedWeakGridsMatchSerialOn1To4Ranks) {
    Scratch s("weak");
    expect_same_as_serial(shared("sphere_weak_d5.leaves"), Balance::Weak, s.dir, {1, 2, 3, 4});
    expect_same_as_serial(shared("sphere_weak_d6.leaves"), Balance::Weak, s.dir, {3});  // E-MR, VC3-MR leaves
}

TEST(Distributed, MirrorRootBoundaryMatchesSerial) {
    Scratch s("mirror");
    expect_same_as_serial(shared("sphere_strong_d5.leaves"), Balance::Strong, s.dir, {2}, OutsideRoot::Mirror);
}

TEST(Distributed, RandomGridsPairedAndBalancedByP8estMatchSerial) {
    // Unbalanced, unpaired random octrees: p8est balances and the pairing fixed point runs.
    Scratch s("random");
    int rounds = 0;
    for (unsigned seed : {1U, 2U, 5U}) {
        const fs::path file = s.dir / ("random" + std::to_string(seed) + ".leaves");
        write_leaf_file(test::random_grid(seed, 5, 0.22), file);
        for (const Balance b : {Balance::Strong, Balance::Weak})
            rounds += expect_same_as_serial(file, b, s.dir, {1 + static_cast<int>(seed % 4), 4});
    }
    EXPECT_GT(rounds, 0) << "some random grid needs the pairing fixed point";
}

TEST(Distributed, PvtuIndexesOnePiecePerRankWithGlobalVertexIds) {
    Scratch s("pvtu");
    const fs::path prefix = s.dir / "mesh";
    const auto r = run_dist(3, {shared("sphere_weak_d5.leaves").string(), "-o", prefix.string(), "--json"}, s.dir);
    ASSERT_EQ(r.rc, 0) << r.err;
    const nlohmann::json doc = nlohmann::json::parse(r.out);
    const std::string index = test::slurp(prefix.string() + ".pvtu");
    std::size_t hexes = 0;
    std::vector<std::uint64_t> ids;
    for (int rank = 0; rank < 3; ++rank) {
        const std::string piece = "mesh_" + std::to_string(rank) + ".vtu";
        EXPECT_NE(index.find("<Piece Source=\"" + piece + "\"/>"), std::string::npos) << index;
        const std::string text = test::slurp(s.dir / piece);
        std::smatch m;
        ASSERT_TRUE(std::regex_search(text, m, std::regex("NumberOfCells=\"(\\d+)\"")));
        hexes += std::stoul(m[1]);
        const auto a = text.find("Name=\"vertex_id\""), b = text.find("</DataArray>", a);
        std::istringstream in(text.substr(text.find('>', a) + 1, b - text.find('>', a) - 1));
        for (std::uint64_t id; in >> id;) ids.push_back(id);
    }
    EXPECT_EQ(hexes, doc["summary"]["hexes"].get<std::size_t>());
    std::sort(ids.begin(), ids.end());  // the owned vertices' global ids: 0 .. V-1, each once
    ASSERT_EQ(ids.size(), doc["summary"]["vertices"].get<std::size_t>());
    for (std::size_t n = 0; n < ids.size(); ++n) ASSERT_EQ(ids[n], n);
    // Without --force an existing output is refused before any work.
    const auto again = run_dist(2, {shared("sphere_weak_d5.leaves").string(), "-o", prefix.string()}, s.dir);
    EXPECT_EQ(again.rc, 2);
    EXPECT_NE(again.err.find("exists"), std::string::npos) << again.err;
    fs::remove(prefix.string() + ".pvtu");  // a piece alone is refused too, by name
    const auto piece = run_dist(2, {shared("sphere_weak_d5.leaves").string(), "-o", prefix.string()}, s.dir);
    EXPECT_EQ(piece.rc, 2);
    EXPECT_NE(piece.err.find("mesh_0.vtu exists"), std::string::npos) << piece.err;
}

TEST(Distributed, BadInputIsALocatedErrorOnEveryRankCount) {
    Scratch s("bad");
    const fs::path bad = s.dir / "bad.leaves";
    std::ofstream(bad) << "1 0 0 0\n1 0 zero 1\n";
    for (int np : {1, 3}) {
        const auto r = run_dist(np, {bad.string()}, s.dir);
        EXPECT_EQ(r.rc, 3) << r.err;
        EXPECT_NE(r.err.find("bad.leaves:2:"), std::string::npos) << r.err;
    }
    const fs::path deep = s.dir / "deep.leaves";
    {
        std::ofstream out(deep);  // one level-19 corner leaf and its siblings, beyond p8est's 18
        std::vector<Leaf> leaves{Leaf{}};
        for (int l = 0; l < 19; ++l) {
            const Leaf c = leaves.front();
            leaves.erase(leaves.begin());
            const auto ch = children(c);
            leaves.insert(leaves.begin(), ch.begin(), ch.end());
        }
        for (const Leaf& l : leaves) out << to_string(l) << '\n';
    }
    const auto r = run_dist(2, {deep.string()}, s.dir);
    EXPECT_EQ(r.rc, 3);
    EXPECT_NE(r.err.find("beyond p8est's 18"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace dualhex
