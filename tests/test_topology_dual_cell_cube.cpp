// The oriented-cube check of one clipped dual cell (topology/src/dual_cell_cube.hpp, internal):
// a consistently oriented cube passes, and each kind of broken cell is named.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "../topology/src/dual_cell_cube.hpp"

namespace dualhex::detail {
namespace {

// The unit cube's faces over its corners (bit 0 = x, 1 = y, 2 = z), all outward.
const std::vector<std::vector<std::uint32_t>> kCube = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

DualCellFaces faces_of(const std::vector<std::vector<std::uint32_t>>& loops) {
    DualCellFaces f;
    for (const auto& loop : loops) {
        f.open();
        for (std::uint32_t v : loop) f.push(v);
    }
    return f;
}

std::string reason(const std::vector<std::vector<std::uint32_t>>& loops) {
    std::array<std::uint32_t, 8> hex{};
    const char* why = oriented_cube(faces_of(loops), hex);
    return why ? why : "";
}

TEST(TopologyDualCellCube, AConsistentCubeIsAHex) {
    std::array<std::uint32_t, 8> hex{};
    ASSERT_EQ(oriented_cube(faces_of(kCube), hex), nullptr);
    std::array<std::uint32_t, 8> sorted = hex;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, (std::array<std::uint32_t, 8>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(TopologyDualCellCube, BrokenCellsAreNamed) {
    auto reversed = kCube;
    std::reverse(reversed[2].begin(), reversed[2].end());
    EXPECT_NE(reason(reversed).find("walked twice"), std::string::npos);
    auto one_face = kCube;
    one_face[0][0] = 1;  // edges 1 -> 4 and 2 -> 1 have no reverse, and none is walked twice
    EXPECT_EQ(reason(one_face), "a dual edge in only one dual face");
    auto triangle = kCube;
    triangle[3].pop_back();
    EXPECT_EQ(reason(triangle), "a dual face that is not a quadrilateral");
    auto nine = kCube;
    nine[5][3] = 9;  // a ninth dual vertex
    EXPECT_EQ(reason(nine), "more than 8 dual vertices");
    auto five = kCube;
    five.pop_back();
    EXPECT_EQ(reason(five), "fewer than 6 dual faces");
}

}  // namespace
}  // namespace dualhex::detail
