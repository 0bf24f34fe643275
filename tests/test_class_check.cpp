// The class-by-class check (checkers/src/class_check.hpp): a member's outcome is its
// representative's only when its complex is proved the exact image; a member with the same
// key that is not an image, a member without a key and the members of a failing
// representative are each checked themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <optional>
#include <vector>

#include "../checkers/src/class_check.hpp"
#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/primitives.hpp"

namespace dualhex {
namespace {

CellComplex cube_at(const LatticePoint& corner, bool reversed = false) {
    auto loops = cube_loops(corner);
    if (reversed)
        for (auto& l : loops) std::reverse(l.begin(), l.end());
    ComplexBuilder b;
    b.add_cell_from_loops(loops);
    return std::move(b).build();
}

struct Family {
    std::vector<CellComplex> complexes;
    std::vector<std::optional<std::pair<int, CubeSymmetry>>> keys;
};

struct Checked {
    std::vector<int> ok;  // 1: passed
    std::vector<int> full_checks;  // per window: how often it was checked itself
};

// The check under test (any fixed rule would do): a window passes iff its points lie in
// [-1, 1]^3.
int passes(const CellComplex& k) {
    for (const LatticePoint& p : k.positions())
        for (int a = 0; a < 3; ++a)
            if (p[a] < -1 || p[a] > 1) return 0;
    return 1;
}

Checked run(const Family& f) {
    const std::size_t n = f.complexes.size();
    std::vector<std::atomic<int>> calls(n);
    const auto check_built = [&](std::size_t i, const CellComplex& k) {
        ++calls[i];
        return passes(k);
    };
    const std::vector<int> out = detail::check_by_class<int, CellComplex, int>(
        n, [&](std::size_t i) { return f.keys[i]; },
        [&](std::size_t i, CellComplex* keep) {
            const int ok = check_built(i, f.complexes[i]);
            if (keep) *keep = f.complexes[i];
            return ok;
        },
        [&](std::size_t i) { return f.complexes[i]; }, check_built,
        [](const CellComplex& k, const CubeSymmetry& s) {
            return detail::oriented_form(k, [&](const LatticePoint& p) { return s.apply(p); }, !s.is_rotation());
        },
        [](int ok) { return ok == 1; });
    Checked c{out, {}};
    for (auto& k : calls) c.full_checks.push_back(k.load());
    return c;
}

const CubeSymmetry kIdentity;
const CubeSymmetry kMirrorX({0, 1, 2}, {-1, 1, 1});  // x -> -x

TEST(ClassCheck, ImagesShareTheOutcomeOthersAreCheckedThemselves) {
    Family f;
    // 0: representative, passes. 1: its image under x -> -x (key reached by that mirror).
    f.complexes.push_back(cube_at({0, 0, 0}));
    f.keys.emplace_back(std::pair{7, kIdentity});
    f.complexes.push_back(cube_at({-1, 0, 0}));
    f.keys.emplace_back(std::pair{7, kMirrorX});
    // 2: the same key but no image of 0 (a cube far away): must be checked, and fails.
    f.complexes.push_back(cube_at({5, 5, 5}));
    f.keys.emplace_back(std::pair{7, kIdentity});
    // 3: no key: checked itself.
    f.complexes.push_back(cube_at({0, 0, 0}));
    f.keys.emplace_back(std::nullopt);
    const Checked c = run(f);
    EXPECT_EQ(c.ok, (std::vector<int>{1, 1, 0, 1}));
    EXPECT_EQ(c.full_checks, (std::vector<int>{1, 0, 1, 1}));  // the image carried over, unchecked
}

TEST(ClassCheck, ReversedOrientationIsNoImage) {
    Family f;
    f.complexes.push_back(cube_at({0, 0, 0}));
    f.keys.emplace_back(std::pair{1, kIdentity});
    // the same cube with every face reversed: same points, not the same oriented complex
    f.complexes.push_back(cube_at({0, 0, 0}, true));
    f.keys.emplace_back(std::pair{1, kIdentity});
    // the reflection of the cube, with its loops as built (outward): an image under x -> -x
    f.complexes.push_back(cube_at({-1, 0, 0}));
    f.keys.emplace_back(std::pair{1, kMirrorX});
    const Checked c = run(f);
    EXPECT_EQ(c.full_checks, (std::vector<int>{1, 1, 0}));
}

TEST(ClassCheck, MembersOfAFailingRepresentativeAreCheckedThemselves) {
    Family f;
    f.complexes.push_back(cube_at({4, 0, 0}));  // fails
    f.keys.emplace_back(std::pair{2, kIdentity});
    f.complexes.push_back(cube_at({-5, 0, 0}));  // its image under x -> -x, fails too
    f.keys.emplace_back(std::pair{2, kMirrorX});
    const Checked c = run(f);
    EXPECT_EQ(c.ok, (std::vector<int>{0, 0}));
    EXPECT_EQ(c.full_checks, (std::vector<int>{1, 1}));
}

}  // namespace
}  // namespace dualhex
