// The configuration check by congruence (checkers/src/congruence_check.hpp): a member whose
// complex is the image of its representative's under some motion of the coset m0 Stab
// carries the representative's report unchecked, even when the rule is not equivariant (the
// first motion m0 does not reproduce it); a member of the same orbit that is no image, and
// the members of a failing representative, are each checked themselves.
#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "../checkers/src/congruence_check.hpp"
#include "dualhex/topology/complex_builder.hpp"
#include "dualhex/topology/primitives.hpp"

namespace dualhex {
namespace {

// Window octant b: on the + side of axis a iff bit a; a mask moved by a symmetry about 0.
std::uint8_t moved_mask(std::uint8_t mask, const CubeSymmetry& s) {
    unsigned out = 0;
    for (int b = 0; b < 8; ++b) {
        const LatticePoint img = s.apply({b & 1 ? 1 : -1, b & 2 ? 1 : -1, b & 4 ? 1 : -1});
        out |= ((mask >> b) & 1U) << ((img.x > 0) | (img.y > 0) << 1 | (img.z > 0) << 2);
    }
    return static_cast<std::uint8_t>(out);
}

// The unit cube in octant b at distance `out` from the origin (0: touching it).
LatticePoint corner(int b, int out) {
    LatticePoint c;
    for (int a = 0; a < 3; ++a) c[a] = (b >> a & 1) ? out : -1 - out;
    return c;
}

// The opposite pairs {b, 7 - b}: one orbit of 4 under the 48 symmetries, each fixed by 12.
const std::vector<std::uint8_t> kPairs = {0x81, 0x42, 0x24, 0x18};

// The "rule": a unit cube in each octant of the mask, and a marker cube one step further
// out in its octant on the +x side only, which breaks the pair's symmetry (not equivariant).
// `far`: the marker of that configuration lands far away instead (no image of any other).
ConfigurationComplex build_pair(std::uint8_t mask, bool far = false) {
    ComplexBuilder b;
    int marked = -1;
    for (int o = 0; o < 8; ++o)
        if (mask >> o & 1) {
            b.add_cell_from_loops(cube_loops(corner(o, 0)));
            if (o & 1) marked = o;
        }
    b.add_cell_from_loops(cube_loops(corner(marked, far ? 5 : 1)));
    ConfigurationComplex out;
    out.mask = mask;
    out.complex = std::move(b).build();
    return out;
}

struct Checked {
    std::vector<int> ok;
    std::vector<int> full_checks;
};

// The check under test: passes iff every point lies in [-limit, limit]^3.
Checked run(const std::vector<bool>& far, std::int64_t limit) {
    const auto classes = detail::congruence(kPairs, detail::all_symmetries(), moved_mask);
    std::vector<std::atomic<int>> calls(kPairs.size());
    const auto build = [&](std::size_t i) { return build_pair(kPairs[i], far[i]); };
    const auto check = [&](std::size_t i, ConfigurationComplex& built) {
        ++calls[i];
        built = build(i);
        ConfigurationReport r;
        r.mask = built.mask;
        r.built = true;
        for (const LatticePoint& p : built.complex.positions())
            for (int a = 0; a < 3; ++a)
                if (p[a] < -limit || p[a] > limit) r.built = false;
        return r;
    };
    const auto reports = detail::check_by_congruence(classes, check, build, detail::symmetric_form);
    Checked out;
    for (std::size_t i = 0; i < kPairs.size(); ++i) {
        out.ok.push_back(reports[i].ok());
        out.full_checks.push_back(calls[i].load());
        EXPECT_EQ(reports[i].mask, kPairs[i]);
    }
    return out;
}

TEST(CongruenceCheck, TheFamilyNeedsTheStabilizer) {
    const auto classes = detail::congruence(kPairs, detail::all_symmetries(), moved_mask);
    ASSERT_EQ(classes.representative, (std::vector<std::size_t>{0, 0, 0, 0}));
    EXPECT_EQ(classes.stabilizer[0].size(), 12U);
    // Some member is not the image of the representative under the first motion found.
    const auto rep = detail::symmetric_form(build_pair(kPairs[0]).complex, CubeSymmetry{});
    int direct = 0;
    for (std::size_t i = 1; i < kPairs.size(); ++i)
        direct += detail::symmetric_form(build_pair(kPairs[i]).complex, classes.motion[i].inverse()) == rep;
    EXPECT_LT(direct, 3);
}

TEST(CongruenceCheck, ImagesUnderTheCosetShareTheReport) {
    const Checked r = run({false, false, false, false}, 2);
    EXPECT_EQ(r.ok, (std::vector<int>{1, 1, 1, 1}));
    EXPECT_EQ(r.full_checks, (std::vector<int>{1, 0, 0, 0}));
}

TEST(CongruenceCheck, AMemberThatIsNoImageIsCheckedItself) {
    // Member 2's marker is far out: same orbit, no image; it fails its own check.
    const Checked fails = run({false, false, true, false}, 2);
    EXPECT_EQ(fails.ok, (std::vector<int>{1, 1, 0, 1}));
    EXPECT_EQ(fails.full_checks, (std::vector<int>{1, 0, 1, 0}));
    // With a looser check it passes, but still on its own check.
    const Checked passes = run({false, false, true, false}, 8);
    EXPECT_EQ(passes.ok, (std::vector<int>{1, 1, 1, 1}));
    EXPECT_EQ(passes.full_checks, (std::vector<int>{1, 0, 1, 0}));
}

TEST(CongruenceCheck, MembersOfAFailingRepresentativeAreCheckedThemselves) {
    const Checked r = run({true, false, false, false}, 2);  // the representative fails
    EXPECT_EQ(r.ok, (std::vector<int>{0, 1, 1, 1}));
    EXPECT_EQ(r.full_checks, (std::vector<int>{1, 1, 1, 1}));
}

}  // namespace
}  // namespace dualhex
