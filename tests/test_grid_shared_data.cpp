// The shared grids (/work/shared/data/grids) are tiled, paired and balanced as named, and
// balancing/pairing them again changes nothing (they are fixed points).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "dualhex/grid/leaf_file.hpp"
#include "dualhex/grid/predicates.hpp"
#include "dualhex/grid/refinement.hpp"

using namespace dualhex;

namespace {

struct SharedGrid {
    const char* name;
    std::size_t leaves;
    int min_level, max_level;
    bool strong;
};

const SharedGrid kGrids[] = {
    {"sphere_strong_d5", 11264, 4, 5, true}, {"sphere_strong_d6", 39040, 4, 6, true},
    {"sphere_strong_d7", 172096, 4, 7, true}, {"sphere_weak_d5", 10816, 3, 5, false},
    {"sphere_weak_d6", 35456, 3, 6, false},   {"sphere_weak_d7", 152832, 3, 7, false},
};

}  // namespace

TEST(SharedGrids, AreTiledPairedAndBalancedAsNamed) {
    for (const SharedGrid& s : kGrids) {
        const auto path = std::filesystem::path(DUALHEX_SHARED_DATA) / "grids" / (std::string(s.name) + ".leaves");
        const LeafGrid g = read_leaf_file(path);  // throws unless it tiles
        EXPECT_EQ(g.size(), s.leaves) << s.name;
        EXPECT_EQ(g.min_level(), s.min_level) << s.name;
        EXPECT_EQ(g.max_level(), s.max_level) << s.name;
        const auto paired = is_paired(g);
        EXPECT_TRUE(paired.ok) << s.name << ": " << paired.message;
        const auto weak = is_weakly_balanced(g);
        EXPECT_TRUE(weak.ok) << s.name << ": " << weak.message;
        const auto strong = is_strongly_balanced(g);
        EXPECT_EQ(strong.ok, s.strong) << s.name << ": " << strong.message;
        const Balance mode = s.strong ? Balance::Strong : Balance::Weak;
        EXPECT_EQ(pair(g, mode).size(), g.size()) << s.name << " is not a fixed point";
    }
}
