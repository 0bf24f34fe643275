// Chain-crossing variants (issue 4): construction, verification, classes, ranking.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "dualhex/checkers/variants_report.hpp"
#include "dualhex/schemes/element_check.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/variants.hpp"
#include "dualhex/topology/histograms.hpp"

using namespace dualhex;
using namespace dualhex::variants;
using Hist = std::map<int, std::size_t>;

namespace {

const ElementLibrary& shipped() {
    static const ElementLibrary lib = ElementLibrary::load_default();
    return lib;
}

const VariantsReport& report() {
    static const VariantsReport r = check_variants(false);
    return r;
}

const RegionReport& region(Region r) {
    for (const auto& x : report().regions)
        if (x.region == r) return x;
    throw std::logic_error("region missing");
}

const VariantResult& result(Region r, const std::string& assignment) {
    for (const auto& v : region(r).variants)
        if (v.assignment == assignment) return v;
    throw std::logic_error("assignment missing");
}

}  // namespace

TEST(Variants, EveryAssignmentIsAValidElement) {
    for (Region r : {Region::Flat, Region::ConcaveEdge, Region::ConcaveCorner}) {
        const auto vs = region_variants(r);
        ASSERT_EQ(vs.size(), assignment_count(r));
        for (const auto& v : vs) {
            const auto check = check_element(v.complex, ElementBox{{0, 0, 0}, kLeaf}, v.labels);
            EXPECT_TRUE(check.ok()) << v.name;
            EXPECT_EQ(v.labels.back(), "lid") << v.name;
            EXPECT_EQ(v.bend_cells.size(), r == Region::Flat ? 0u : r == Region::ConcaveEdge ? 1u : 3u) << v.name;
        }
    }
}

TEST(Variants, UnknownAssignmentThrows) {
    EXPECT_THROW((void)build_variant(Region::ConcaveEdge, "LX"), std::invalid_argument);
    EXPECT_THROW((void)build_variant(Region::ConcaveCorner, "XYX"), std::invalid_argument);
}

TEST(Variants, OptimalAssignmentsAreTheShippedElements) {
    const std::map<std::pair<Region, std::string>, std::string> expected{
        {{Region::Flat, "x"}, "F"},     {{Region::Flat, "z"}, "F"},
        {{Region::ConcaveEdge, "LL"}, "E"}, {{Region::ConcaveEdge, "LU"}, "VS"}, {{Region::ConcaveEdge, "UL"}, "VS"},
        {{Region::ConcaveCorner, "XYZ"}, "VC"}, {{Region::ConcaveCorner, "ZXY"}, "VC"}};
    for (Region r : {Region::Flat, Region::ConcaveEdge, Region::ConcaveCorner})
        for (const auto& v : region_variants(r)) {
            const auto it = expected.find({r, v.assignment});
            const ComplexForm form = canonical_form(v.complex);
            std::string match;
            for (const auto& e : shipped().elements())
                if (canonical_form(e.complex) == form) match = e.name;
            EXPECT_EQ(match, it == expected.end() ? "" : it->second) << v.name;
        }
    // In the shipped frames the canonical assignments are equal without any symmetry.
    EXPECT_EQ(complex_form(build_variant(Region::Flat, "x").complex), complex_form(shipped().at("F").complex));
    EXPECT_EQ(complex_form(build_variant(Region::ConcaveEdge, "LL").complex), complex_form(shipped().at("E").complex));
    EXPECT_EQ(complex_form(build_variant(Region::ConcaveEdge, "LU").complex), complex_form(shipped().at("VS").complex));
    EXPECT_EQ(complex_form(build_variant(Region::ConcaveCorner, "XYZ").complex),
              complex_form(shipped().at("VC").complex));
    // UL is VS mirrored in y <-> z: exactly one of the 6 leaf symmetries maps it.
    const auto maps = symmetries_mapping(shipped().at("VS").complex, build_variant(Region::ConcaveEdge, "UL").complex);
    ASSERT_EQ(maps.size(), 1u);
    EXPECT_EQ(maps.front(), CubeSymmetry({0, 2, 1}, {1, 1, 1}));
}

TEST(Variants, EveryAssignmentPassesItsTorus) {
    EXPECT_TRUE(report().ok());
    for (const auto& r : report().regions) {
        EXPECT_EQ(r.valid, assignment_count(r.region)) << to_string(r.region);
        for (const auto& v : r.variants) {
            EXPECT_TRUE(v.torus.ok()) << v.torus.summary();
            ASSERT_EQ(v.torus.elements.count(v.name), 1u) << v.torus.summary();
            EXPECT_EQ(v.torus.elements.at(v.name), r.region == Region::Flat ? 32u : r.region == Region::ConcaveEdge ? 16u : 8u);
            EXPECT_EQ(v.torus.hexes, v.torus.checked_vertices);
        }
    }
}

TEST(Variants, ClassesAre1_3_2) {
    EXPECT_EQ(region(Region::Flat).classes.size(), 1u);
    EXPECT_EQ(region(Region::ConcaveEdge).classes.size(), 3u);
    EXPECT_EQ(region(Region::ConcaveCorner).classes.size(), 2u);
    auto members = [](Region r, std::size_t k) {
        std::string s;
        for (std::size_t m : region(r).classes[k].members) s += region(r).variants[m].assignment + " ";
        return s;
    };
    EXPECT_EQ(members(Region::Flat, 0), "x z ");
    EXPECT_EQ(members(Region::ConcaveEdge, 0), "LL ");
    EXPECT_EQ(members(Region::ConcaveEdge, 1), "LU UL ");
    EXPECT_EQ(members(Region::ConcaveEdge, 2), "UU ");
    EXPECT_EQ(members(Region::ConcaveCorner, 0), "XYZ ZXY ");
    EXPECT_EQ(members(Region::ConcaveCorner, 1), "XXY XXZ XYY ZXZ ZYY ZYZ ");
    for (const auto& r : report().regions)
        for (std::size_t k = 0; k < r.classes.size(); ++k) {
            EXPECT_EQ(r.classes[k].rank, static_cast<int>(k) + 1);
            EXPECT_TRUE(r.classes[k].histograms_agree);
        }
}

TEST(Variants, PinnedHistograms) {
    struct Row {
        Region region;
        const char* assignment;
        Hist element, bend, torus;
        int bend_face_size;
    };
    const Row rows[] = {
        {Region::Flat, "x", {{3, 5}, {4, 10}, {5, 5}}, {}, {{3, 96}, {4, 960}, {5, 96}}, 0},
        {Region::ConcaveEdge, "LL", {{3, 8}, {4, 14}, {5, 7}, {6, 1}}, {{3, 2}, {4, 2}, {5, 2}},
         {{3, 80}, {4, 1280}, {5, 80}, {6, 8}}, 5},
        {Region::ConcaveEdge, "LU", {{3, 8}, {4, 16}, {5, 3}, {6, 3}}, {{3, 2}, {4, 3}, {6, 2}},
         {{3, 80}, {4, 1304}, {5, 32}, {6, 32}}, 6},
        {Region::ConcaveEdge, "UU", {{3, 9}, {4, 16}, {5, 2}, {6, 1}, {7, 2}}, {{3, 2}, {4, 4}, {7, 2}},
         {{3, 88}, {4, 1312}, {5, 16}, {6, 8}, {7, 24}}, 7},
        {Region::ConcaveCorner, "XYZ", {{3, 9}, {4, 21}, {6, 6}}, {{3, 6}, {4, 9}, {6, 6}},
         {{3, 48}, {4, 1440}, {6, 36}}, 6},
        {Region::ConcaveCorner, "XXY", {{3, 10}, {4, 19}, {5, 3}, {6, 2}, {7, 2}},
         {{3, 6}, {4, 9}, {5, 2}, {6, 2}, {7, 2}}, {{3, 52}, {4, 1432}, {5, 16}, {6, 12}, {7, 12}}, 7},
    };
    for (const auto& row : rows) {
        const auto& v = result(row.region, row.assignment);
        EXPECT_EQ(v.element_faces, row.element) << v.name;
        EXPECT_EQ(v.bend_faces, row.bend) << v.name;
        EXPECT_EQ(v.torus.dual_edge_valences, row.torus) << v.name;
        EXPECT_EQ(v.bend_face_size, row.bend_face_size) << v.name;
    }
    EXPECT_EQ(singular_edges(result(Region::ConcaveEdge, "LL").torus.dual_edge_valences), 168u);
    EXPECT_EQ(singular_edges(result(Region::ConcaveCorner, "XYZ").torus.dual_edge_valences), 84u);
}

TEST(Variants, RankingKey) {
    EXPECT_LT(ranking_key({{3, 80}, {4, 1280}, {5, 80}, {6, 8}}), ranking_key({{3, 80}, {4, 1304}, {5, 32}, {6, 32}}));
    EXPECT_LT(ranking_key({{3, 80}, {4, 1304}, {5, 32}, {6, 32}}),
              ranking_key({{3, 88}, {4, 1312}, {5, 16}, {6, 8}, {7, 24}}));
    EXPECT_EQ(ranking_key({{3, 1}, {4, 2}}), ranking_key({{3, 7}, {4, 9}}));  // valences <= 4 do not count
}

TEST(Variants, FlippedBendFaceFailsVerification) {
    const Variant v = build_variant(Region::ConcaveEdge, "LL");
    ASSERT_EQ(v.bend_cells.size(), 1u);
    Variant m = v;
    auto halffaces = v.complex.all_cell_halffaces();
    const std::size_t first = v.complex.cell_offsets()[static_cast<std::size_t>(v.bend_cells.front())];
    halffaces[first] = halffaces[first].opposite();
    m.complex = CellComplex(v.complex.positions(), v.complex.face_offsets(), v.complex.face_loops(),
                            v.complex.cell_offsets(), halffaces);
    const VariantResult bad = check_variant(m, &shipped());
    EXPECT_FALSE(bad.element_valid);
    EXPECT_FALSE(bad.torus.ok());
    EXPECT_FALSE(bad.ok());
    const VariantResult good = check_variant(v, &shipped());
    EXPECT_TRUE(good.ok()) << good.torus.summary();
    EXPECT_EQ(good.shipped, "E");
}

TEST(Variants, SubstitutingRuleKeepsOtherPlacements) {
    const StrongRule strong;
    const SubstitutingRule rule(strong, "E", "edge-UU");
    LeafContext c;
    c.set_fine(0, -1, 0);  // one interface face (y): F, untouched
    const auto p = rule.place(c);
    ASSERT_TRUE(p);
    EXPECT_EQ(p->element, strong.place(c)->element);
    c.set_fine(0, 0, -1);  // concave edge: E -> edge-UU
    EXPECT_EQ(rule.place(c)->element, "edge-UU");
}

TEST(Variants, CombinedSmallClassesStrongRuleOptimal) {
    const CombinedReport r = check_combined(shipped(), 6);
    EXPECT_EQ(r.classes.size(), 20u);
    std::size_t enumerated = 0;
    for (const auto& c : r.classes) {
        if (!c.enumerated) continue;
        ++enumerated;
        EXPECT_EQ(c.valid, c.assignments) << format_mask(c.representative);
        EXPECT_TRUE(c.strong_optimal()) << format_mask(c.representative);
        EXPECT_GE(c.assignments_equal, 1u) << format_mask(c.representative);
        EXPECT_EQ(c.best_valences, c.strong_valences) << format_mask(c.representative);
    }
    EXPECT_GE(enumerated, 6u);
}
