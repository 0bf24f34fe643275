#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>

#include "dualhex/topology/cube_symmetry.hpp"

using dualhex::CubeSymmetry;
using dualhex::LatticePoint;

TEST(CubeSymmetry, IsAGroupOfOrder48With24Rotations) {
    std::set<int> seen;
    int rotations = 0;
    for (int i = 0; i < CubeSymmetry::kOrder; ++i) {
        const auto s = CubeSymmetry::from_index(i);
        EXPECT_EQ(s.index(), i);
        seen.insert(s.index());
        if (s.is_rotation()) ++rotations;
        EXPECT_EQ(s.compose(s.inverse()), CubeSymmetry{});
        EXPECT_EQ(s.inverse().compose(s), CubeSymmetry{});
        for (int j = 0; j < CubeSymmetry::kOrder; ++j)  // closure
            EXPECT_LT(s.compose(CubeSymmetry::from_index(j)).index(), CubeSymmetry::kOrder);
    }
    EXPECT_EQ(seen.size(), 48u);
    EXPECT_EQ(rotations, 24);
    EXPECT_EQ(CubeSymmetry::from_index(0), CubeSymmetry{});
}

RC_GTEST_PROP(CubeSymmetry, ActionsCompose, (int a, int b, std::int32_t x, std::int32_t y, std::int32_t z)) {
    const auto s = CubeSymmetry::from_index(((a % 48) + 48) % 48);
    const auto t = CubeSymmetry::from_index(((b % 48) + 48) % 48);
    const LatticePoint p{x, y, z};
    RC_ASSERT(s.compose(t).apply(p) == s.apply(t.apply(p)));
    RC_ASSERT(s.inverse().apply(s.apply(p)) == p);
    RC_ASSERT(s.compose(t).apply_about(p, 7) == s.apply_about(t.apply_about(p, 7), 7));
}

RC_GTEST_PROP(CubeSymmetry, DeterminantIsMultiplicative, (int a, int b)) {
    const auto s = CubeSymmetry::from_index(((a % 48) + 48) % 48);
    const auto t = CubeSymmetry::from_index(((b % 48) + 48) % 48);
    RC_ASSERT(s.compose(t).determinant() == s.determinant() * t.determinant());
}
