// Leaf helpers: parent/children/ancestor, boxes at a finer level, validity, the hash map.
#include <gtest/gtest.h>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/input_error.hpp"
#include "dualhex/grid/leaf.hpp"

using namespace dualhex;

TEST(Leaf, ParentChildrenAncestor) {
    const Leaf l{3, 5, 2, 7};
    EXPECT_EQ(parent(l), (Leaf{2, 2, 1, 3}));
    EXPECT_EQ(ancestor(l, 1), (Leaf{1, 1, 0, 1}));
    EXPECT_EQ(ancestor(l, 3), l);
    const auto kids = children(l);
    for (int c = 0; c < 8; ++c) {
        EXPECT_EQ(parent(kids[c]), l);
        EXPECT_EQ(child_index(kids[c]), c);
        EXPECT_TRUE(contains(l, kids[c]));
        EXPECT_FALSE(contains(kids[c], l));
    }
    EXPECT_EQ(kids[5], (Leaf{4, 11, 4, 15}));
    EXPECT_FALSE(contains(Leaf{1, 0, 0, 0}, Leaf{2, 2, 0, 0}));
}

TEST(Leaf, BoxAtFinerLevelAndToString) {
    const LeafBox b = box_at(Leaf{2, 1, 3, 0}, 5);
    EXPECT_EQ(b.lo, (LatticePoint{8, 24, 0}));
    EXPECT_EQ(b.hi, (LatticePoint{16, 32, 8}));
    EXPECT_EQ(b.level, 5);
    EXPECT_EQ(to_string(Leaf{2, 1, 3, 0}), "2 1 3 0");
}

TEST(Leaf, Validity) {
    EXPECT_TRUE((Leaf{0, 0, 0, 0}).valid());
    EXPECT_TRUE((Leaf{30, (1 << 30) - 1, 0, 5}).valid());
    EXPECT_FALSE((Leaf{31, 0, 0, 0}).valid());
    EXPECT_FALSE((Leaf{-1, 0, 0, 0}).valid());
    EXPECT_FALSE((Leaf{2, 4, 0, 0}).valid());
    EXPECT_FALSE((Leaf{2, 0, -1, 0}).valid());
}

TEST(CellMap, PackRoundTripAndGrowth) {
    const Leaf deep{30, (1 << 30) - 1, 12345, (1 << 30) - 2};
    EXPECT_EQ(unpack(pack(deep)), deep);
    EXPECT_EQ(unpack(pack(Leaf{})), Leaf{});
    CellMap<int> map;
    for (int i = 0; i < 5000; ++i) EXPECT_TRUE(map.insert(Leaf{13, i, 2 * i, 3 * i}, i).second);
    EXPECT_FALSE(map.insert(Leaf{13, 7, 14, 21}, 99).second);
    EXPECT_EQ(map.size(), 5000u);
    for (int i = 0; i < 5000; ++i) ASSERT_EQ(*map.find(Leaf{13, i, 2 * i, 3 * i}), i);
    EXPECT_EQ(map.find(Leaf{12, 7, 14, 21}), nullptr);  // same position, other level
}

TEST(InputError, Format) {
    EXPECT_STREQ(InputError("a.leaves", 4, "bad").what(), "a.leaves:4: bad");
    EXPECT_STREQ(InputError("a.leaves", 0, "bad").what(), "a.leaves: bad");
    EXPECT_STREQ(InputError("", 0, "bad").what(), "bad");
    const InputError e("f", 2, "m");
    EXPECT_EQ(e.file(), "f");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.message(), "m");
}
