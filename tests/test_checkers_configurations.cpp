// Checkers: rule interface, torus and cube-window configurations, exhaustive run.
// The element is the pinned F of test_checkers_fixture.hpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dualhex/checkers/cube_window.hpp"
#include "dualhex/checkers/exhaustive.hpp"
#include "dualhex/checkers/periodic_configuration.hpp"
#include "dualhex/grid/configurations.hpp"
#include "dualhex/schemes/element_library.hpp"
#include "dualhex/schemes/placement.hpp"
#include "dualhex/topology/incidence.hpp"
#include "test_checkers_fixture.hpp"

namespace dualhex {
namespace {


const ElementLibrary& flat_library() {
    static const ElementLibrary lib = [] {
        const auto dir = testing::write_flat_element_dir("cfg");
        ElementLibrary l = ElementLibrary::load(dir);
        std::filesystem::remove_all(dir);
        return l;
    }();
    return lib;
}

constexpr std::uint8_t kFlatMask = 0b11001100;  // octant cubes with y in [2,4) fine

// F reflected everywhere (x <-> z): consistent, so still valid (the crossing choice is
// harmless on a flat region).
class AllSwappedRule : public TransitionRule {
public:
    std::optional<Placement> place(const LeafContext& ctx) const override {
        auto p = FlatOnlyRule().place(ctx);
        if (p) p->symmetry = CubeSymmetry({2, 1, 0}, {1, 1, 1});
        return p;
    }
};

class SignFlipRule : public TransitionRule {
public:
    std::optional<Placement> place(const LeafContext& ctx) const override {
        auto p = FlatOnlyRule().place(ctx);
        if (p) p->symmetry = CubeSymmetry({0, 1, 2}, {-1, 1, 1});
        return p;
    }
};

class UnknownElementRule : public TransitionRule {
public:
    std::optional<Placement> place(const LeafContext& ctx) const override {
        auto p = FlatOnlyRule().place(ctx);
        if (p) p->element = "NoSuchElement";
        return p;
    }
};

TEST(CheckersContext, NeighbourhoodBitsAndNames) {
    LeafContext ctx;
    ctx.set_fine(0, -1, 0);
    ctx.set_fine(-1, -1, 0);
    ctx.set_fine(0, -1, -1);
    ctx.set_fine(-1, -1, -1);
    EXPECT_EQ(ctx.local_pattern_name(), "{Y,XY,YZ,XYZ}");
    EXPECT_TRUE(ctx.fine(-1, -1, -1));
    EXPECT_FALSE(ctx.fine(1, 1, 1));
    EXPECT_THROW((void)ctx.fine(2, 0, 0), std::out_of_range);
    // local configuration in grid convention: the -y octants are bits 0,1,4,5
    EXPECT_EQ(ctx.local_configuration(), 0b00110011);
    ASSERT_TRUE(FlatOnlyRule().place(ctx).has_value());
    EXPECT_EQ(FlatOnlyRule().place(ctx)->element, "F");
    ctx.set_fine(-1, 0, 0);
    EXPECT_THROW((void)FlatOnlyRule().place(ctx), UnknownPatternError);
    // Reflection by d: i <-> -1 - i per negative axis, an involution.
    const std::uint64_t w = 0x0123456789abcdefULL;
    for (int b = 0; b < 8; ++b) {
        const std::array<int, 3> d{b & 1 ? -1 : 1, b & 2 ? -1 : 1, b & 4 ? -1 : 1};
        EXPECT_EQ(to_local_neighbourhood(to_local_neighbourhood(w, d), d), w);
    }
    LeafContext one;
    one.neighbourhood = std::uint64_t{1} << LeafContext::neighbourhood_bit(-2, 0, 1);
    const std::uint64_t r = to_local_neighbourhood(one.neighbourhood, {-1, 1, -1});
    EXPECT_EQ(r, std::uint64_t{1} << LeafContext::neighbourhood_bit(1, 0, -2));
    // world symmetry = diag(d) after s
    ctx.direction = {-1, 1, -1};
    const CubeSymmetry ws = world_symmetry(ctx, Placement{"F", CubeSymmetry{}});
    EXPECT_EQ(ws.apply({1, 2, 3}), (LatticePoint{-1, 2, -3}));
}

TEST(CheckersPeriodic, FlatTorusIsAllHex) {
    const ConfigurationReport r = check_periodic_configuration(kFlatMask, FlatOnlyRule(), flat_library());
    ASSERT_TRUE(r.built) << r.error;
    EXPECT_TRUE(r.validation.ok()) << r.summary();
    EXPECT_TRUE(r.ok()) << r.summary();
    EXPECT_EQ(r.cells, 384U);
    EXPECT_EQ(r.faces, 1152U);
    EXPECT_EQ(r.face_sizes, (std::map<int, std::size_t>{{3, 96}, {4, 960}, {5, 96}}));
    // Closed: every face interior, so the dual histogram equals the face histogram.
    EXPECT_EQ(r.dual_edge_valences, r.face_sizes);
    EXPECT_EQ(r.checked_vertices, r.vertices);
    EXPECT_EQ(r.hexes, r.vertices);
    EXPECT_EQ(r.open_faces, 0U);
    EXPECT_EQ(r.elements.at("F"), 32U);
    EXPECT_EQ(r.elements.at("fine"), 256U);

    // Independently of validate: every vertex 6 edges, every edge 4 cells, no boundary.
    const ConfigurationComplex built = build_periodic_configuration(kFlatMask, FlatOnlyRule(), flat_library());
    EXPECT_EQ(built.unit, 12);
    const Incidence inc(built.complex);
    for (std::size_t v = 0; v < built.complex.n_vertices(); ++v) {
        EXPECT_FALSE(inc.is_boundary(VertexHandle(v)));
        EXPECT_EQ(inc.vertex_edges(VertexHandle(v)).size(), 6U) << built.complex.position(VertexHandle(v));
    }
    for (std::size_t e = 0; e < built.complex.n_edges(); ++e) EXPECT_EQ(inc.edge_cells(EdgeHandle(e)).size(), 4U);
}

TEST(CheckersPeriodic, EveryFlatOrientationPasses) {
    // The 6 masks of the flat class: the rule only knows local y < 0, yet every leaf's
    // local frame sees the same pattern only for the two y-halves.
    for (std::uint8_t m : {std::uint8_t{0b11001100}, std::uint8_t{0b00110011}}) {
        const ConfigurationReport r = check_periodic_configuration(m, FlatOnlyRule(), flat_library());
        EXPECT_TRUE(r.ok()) << r.summary();
        const ConfigurationReport w = check_cube_window(m, FlatOnlyRule(), flat_library());
        EXPECT_TRUE(w.ok()) << w.summary();
    }
    // x-halves: the flat-only rule has no element for local x < 0.
    const ConfigurationReport x = check_periodic_configuration(0b10101010, FlatOnlyRule(), flat_library());
    EXPECT_FALSE(x.built);
    EXPECT_NE(x.error.find("no element for local pattern {X,XY,XZ,XYZ}"), std::string::npos) << x.error;
}

TEST(CheckersPeriodic, ConsistentReflectionStillPasses) {
    const ConfigurationReport r = check_periodic_configuration(kFlatMask, AllSwappedRule(), flat_library());
    EXPECT_TRUE(r.ok()) << r.summary();
}

TEST(CheckersPeriodic, WrongReflectionFailsWithValenceViolations) {
    const ConfigurationReport r = check_periodic_configuration(kFlatMask, testing::SwappedCrossingRule(), flat_library());
    ASSERT_TRUE(r.built) << r.error;
    EXPECT_FALSE(r.ok());
    EXPECT_GT(r.open_faces, 0U);  // the two sides of x = 0 do not match
    EXPECT_GT(r.validation.count(ViolationKind::VertexValence) + r.validation.count(ViolationKind::EdgeCellCount), 0U)
        << r.summary();
    const ConfigurationReport w = check_cube_window(kFlatMask, testing::SwappedCrossingRule(), flat_library());
    ASSERT_TRUE(w.built) << w.error;
    EXPECT_FALSE(w.ok());
    EXPECT_GT(w.validation.count(ViolationKind::VertexValence) + w.validation.count(ViolationKind::EdgeCellCount), 0U)
        << w.summary();
}

TEST(CheckersPeriodic, RuleAndLibraryErrorsAreReportedNotThrown) {
    const ConfigurationReport one = check_periodic_configuration(0b00000001, FlatOnlyRule(), flat_library());
    EXPECT_FALSE(one.built);
    EXPECT_FALSE(one.ok());
    EXPECT_NE(one.error.find("no element for local pattern"), std::string::npos) << one.error;
    EXPECT_THROW((void)build_periodic_configuration(0b00000001, FlatOnlyRule(), flat_library()), UnknownPatternError);

    const ConfigurationReport flip = check_periodic_configuration(kFlatMask, SignFlipRule(), flat_library());
    EXPECT_FALSE(flip.built);
    EXPECT_NE(flip.error.find("moves it out of its leaf"), std::string::npos) << flip.error;

    const ConfigurationReport unknown = check_periodic_configuration(kFlatMask, UnknownElementRule(), flat_library());
    EXPECT_FALSE(unknown.built);
    EXPECT_NE(unknown.error.find("NoSuchElement"), std::string::npos) << unknown.error;
}

TEST(CheckersWindow, FlatWindowChecksOnlyInsideVertices) {
    const ConfigurationReport r = check_cube_window(0b11001100, FlatOnlyRule(), flat_library());
    EXPECT_TRUE(r.ok()) << r.summary();
    // 4 fine octants * 64 + 32 leaves (16 F of 4 cells, 16 hexes).
    EXPECT_EQ(r.elements.at("F"), 16U);
    EXPECT_EQ(r.elements.at("hex"), 16U);
    EXPECT_EQ(r.cells, 256U + 16U * 4U + 16U);
    EXPECT_GT(r.checked_vertices, 0U);
    EXPECT_LT(r.checked_vertices, r.vertices);  // the cube's boundary is not checked
    EXPECT_EQ(r.hexes, r.checked_vertices);
}

TEST(CheckersWindow, TrivialConfigurations) {
    for (std::uint8_t m : {std::uint8_t{0}, std::uint8_t{255}}) {
        const ConfigurationReport p = check_periodic_configuration(m, FlatOnlyRule(), flat_library());
        EXPECT_TRUE(p.ok()) << p.summary();
        EXPECT_EQ(p.face_sizes, (std::map<int, std::size_t>{{4, 3 * p.cells}}));
        const ConfigurationReport w = check_cube_window(m, FlatOnlyRule(), flat_library());
        EXPECT_TRUE(w.ok()) << w.summary();
    }
}

TEST(CheckersExhaustive, FlatOnlyRuleCoversOnlyTrivialClassesAndTwoFlatMasks) {
    const ExhaustiveResult r = run_exhaustive(FlatOnlyRule(), flat_library());
    ASSERT_EQ(r.classes.size(), 22U);
    ASSERT_EQ(r.periodic.size(), 256U);
    int passed_classes = 0, configurations = 0;
    const ConfigurationSpace space(SymmetryGroup::Full);
    for (const ClassSummary& s : r.classes) {
        configurations += s.configurations;
        if (s.passed()) {
            ++passed_classes;
            EXPECT_TRUE(s.representative == 0 || s.representative == 255) << format_mask(s.representative);
        } else {
            EXPECT_FALSE(s.first_error.empty());
        }
    }
    EXPECT_EQ(configurations, 256);
    EXPECT_EQ(passed_classes, 2);
    EXPECT_EQ(r.periodic_passed, 4);  // 0, 255 and the two y-halves (local y < 0 is all it knows)
    EXPECT_EQ(r.window_passed, 4);
    EXPECT_FALSE(r.all_passed());
    // Flat class: 6 members, the 2 y-halves pass on the torus and in the window; its
    // statistics come from the first member that could be built (0b00110011).
    const ClassSummary& flat = r.classes[static_cast<std::size_t>(space.class_of(kFlatMask))];
    EXPECT_EQ(flat.configurations, 6);
    EXPECT_EQ(flat.periodic_passed, 2);
    EXPECT_EQ(flat.window_passed, 2);
    EXPECT_EQ(flat.shown, 0b00110011);
    EXPECT_EQ(flat.cells, 384U);
    EXPECT_EQ(flat.hexes, flat.checked_vertices);
    EXPECT_TRUE(flat.elements.count("F"));
    EXPECT_LT(r.seconds / 512.0, 0.05) << "per configuration";
    std::ostringstream os;
    print(os, r);
    EXPECT_NE(os.str().find("torus 4/256, window 4/256"), std::string::npos) << os.str();
}

}  // namespace
}  // namespace dualhex
