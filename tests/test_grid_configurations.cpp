// The configuration space: class counts computed by enumeration, checked against the
// paper (22 / 20 under 48 symmetries, 23 under rotations) and against Burnside's lemma.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "dualhex/grid/configurations.hpp"

using namespace dualhex;

namespace {

// Burnside: #orbits = average number of fixed masks; per fine count k, counts the
// k-subsets fixed by each element, independently of the orbit enumeration.
std::map<int, int> burnside_orbits_by_fine_count(SymmetryGroup group) {
    const auto elements = group_elements(group);
    std::map<int, int> total;
    for (int k = 0; k <= 8; ++k) {
        int fixed = 0;
        for (const auto& g : elements)
            for (int m = 0; m < 256; ++m)
                if (fine_count(static_cast<ConfigMask>(m)) == k && apply(g, static_cast<ConfigMask>(m)) == m) ++fixed;
        EXPECT_EQ(fixed % static_cast<int>(elements.size()), 0);
        total[k] = fixed / static_cast<int>(elements.size());
    }
    return total;
}

}  // namespace

TEST(Configurations, PaperCounts) {
    const ConfigurationSpace full(SymmetryGroup::Full), rot(SymmetryGroup::Rotations);
    EXPECT_EQ(full.classes().size(), 22u);
    EXPECT_EQ(full.transition_count(), 20);
    EXPECT_EQ(rot.classes().size(), 23u);
    EXPECT_EQ(rot.transition_count(), 21);
}

TEST(Configurations, ClassesPartitionAndMatchBurnside) {
    for (const auto group : {SymmetryGroup::Full, SymmetryGroup::Rotations}) {
        const ConfigurationSpace space(group);
        const int order = static_cast<int>(group_elements(group).size());
        int sum = 0;
        std::map<int, int> per_fine;
        for (const auto& c : space.classes()) {
            sum += c.size;
            EXPECT_EQ(order % c.size, 0) << "orbit size divides the group order";
            ++per_fine[c.fine];
        }
        EXPECT_EQ(sum, 256);
        EXPECT_EQ(per_fine, burnside_orbits_by_fine_count(group));
        for (int m = 0; m < 256; ++m) {
            const auto mask = static_cast<ConfigMask>(m);
            const auto& cls = space.classes()[static_cast<std::size_t>(space.class_of(mask))];
            EXPECT_EQ(apply(space.to_representative(mask), mask), cls.representative);
            EXPECT_LE(cls.representative, mask);
            EXPECT_EQ(cls.fine, fine_count(mask));
        }
    }
}

TEST(Configurations, FullGroupClassSizes) {
    // Derived by hand: k=1: one class of all 8 corners; k=2: pairs along an edge (12),
    // across a face diagonal (12), across the body diagonal (4). Complements mirror k<->8-k.
    const ConfigurationSpace full(SymmetryGroup::Full);
    std::map<int, std::vector<int>> sizes;
    for (const auto& c : full.classes()) sizes[c.fine].push_back(c.size);
    for (auto& [k, v] : sizes) std::sort(v.begin(), v.end());
    EXPECT_EQ(sizes[0], std::vector<int>{1});
    EXPECT_EQ(sizes[1], std::vector<int>{8});
    EXPECT_EQ(sizes[2], (std::vector<int>{4, 12, 12}));
    for (int k = 0; k <= 8; ++k) EXPECT_EQ(sizes[k], sizes[8 - k]) << k;
    int total_k3 = 0;
    for (int s : sizes[3]) total_k3 += s;
    EXPECT_EQ(total_k3, 56);  // C(8,3)
    EXPECT_EQ(std::find(sizes[3].begin(), sizes[3].end(), 24) != sizes[3].end(), true);
}

TEST(Configurations, ActionIsAGroupAction) {
    for (int a = 0; a < 48; ++a)
        for (int b = 0; b < 48; ++b) {
            const auto sa = CubeSymmetry::from_index(a), sb = CubeSymmetry::from_index(b);
            for (int m = 0; m < 256; m += 7) {
                const auto mask = static_cast<ConfigMask>(m);
                ASSERT_EQ(apply(sa.compose(sb), mask), apply(sa, apply(sb, mask)));
            }
        }
    // Octant bit convention: bit 1 is the +x,-y,-z octant.
    EXPECT_EQ(octant_bit(1, -1, -1), 1);
    EXPECT_EQ(octant_signs(6), (LatticePoint{-1, 1, 1}));
}
