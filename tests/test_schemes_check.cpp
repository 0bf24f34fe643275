// Element validation: F and C1 accepted; mutations of F rejected with the right reason.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

#include "dualhex/schemes/element.hpp"
#include "dualhex/schemes/element_check.hpp"

using namespace dualhex;
namespace fs = std::filesystem;

namespace {

ElementData load(const char* name) {
    return read_element_file(fs::path(DUALHEX_SOURCE_DIR) / "schemes" / "elements" / (std::string(name) + ".element"));
}

std::string text(const ElementCheckReport& r) {
    std::ostringstream os;
    r.print(os);
    return os.str();
}

std::size_t cell_index(const ElementData& d, const std::string& label) {
    for (std::size_t i = 0; i < d.cells.size(); ++i)
        if (d.cells[i].label == label) return i;
    ADD_FAILURE() << "no cell " << label;
    return 0;
}

std::set<std::int64_t> as_set(const std::vector<std::int64_t>& f) { return {f.begin(), f.end()}; }

/// Index (in cell `a`) of a face that cell `b` also has.
std::size_t shared_face(const ElementData& d, std::size_t a, std::size_t b) {
    for (std::size_t i = 0; i < d.cells[a].faces.size(); ++i)
        for (const auto& g : d.cells[b].faces)
            if (as_set(d.cells[a].faces[i]) == as_set(g)) return i;
    ADD_FAILURE() << "no shared face";
    return 0;
}

std::int64_t vertex_at(const ElementData& d, LatticePoint p) {
    for (const auto& v : d.vertices)
        if (v.position == p) return v.id;
    ADD_FAILURE() << "no vertex at " << p;
    return -1;
}

bool message_mentions(const ElementCheckReport& r, ElementIssueKind k, const std::string& s) {
    return std::any_of(r.issues.begin(), r.issues.end(),
                       [&](const ElementIssue& i) { return i.kind == k && i.message.find(s) != std::string::npos; });
}

}  // namespace

TEST(SchemesCheck, SeedElementsAreValid) {
    for (const char* name : {"F", "C1"}) {
        const auto d = load(name);
        const auto r = check_element(d);
        EXPECT_TRUE(r.ok()) << name << "\n" << text(r);
        EXPECT_EQ(r.volume6, 6 * 12 * 12 * 12);
        EXPECT_TRUE(r.topology.ok());
    }
}

TEST(SchemesCheck, DropFaceIsRejected) {
    auto d = load("F");
    const auto c = cell_index(d, "p1");
    d.cells[c].faces.erase(d.cells[c].faces.begin());
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.has(ElementIssueKind::Topology));
    EXPECT_TRUE(r.has(ViolationKind::CellOpenEdge)) << text(r);
    EXPECT_TRUE(message_mentions(r, ElementIssueKind::Topology, "'p1'")) << text(r);
}

TEST(SchemesCheck, ReversedInteriorFaceIsRejected) {
    auto d = load("F");
    const auto a = cell_index(d, "p1"), b = cell_index(d, "p2");
    auto& f = d.cells[a].faces[shared_face(d, a, b)];
    std::reverse(f.begin(), f.end());
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.has(ViolationKind::FaceSameOrientation)) << text(r);
    EXPECT_TRUE(r.has(ViolationKind::CellInconsistentOrientation)) << text(r);
}

TEST(SchemesCheck, ReversedBoundaryFaceIsRejected) {
    auto d = load("F");
    const auto lid = cell_index(d, "lid");
    // the lid's face on the top of the leaf (y = 12): all four top corners
    const std::set<std::int64_t> top = {vertex_at(d, {0, 12, 0}), vertex_at(d, {12, 12, 0}), vertex_at(d, {12, 12, 12}),
                                        vertex_at(d, {0, 12, 12})};
    bool found = false;
    for (auto& f : d.cells[lid].faces)
        if (as_set(f) == top) {
            std::reverse(f.begin(), f.end());
            found = true;
        }
    ASSERT_TRUE(found);
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.has(ElementIssueKind::BoundaryFaceInward)) << text(r);
    EXPECT_TRUE(message_mentions(r, ElementIssueKind::BoundaryFaceInward, "+y")) << text(r);
    EXPECT_TRUE(r.has(ElementIssueKind::LeafFaceNotTiled)) << text(r);
    EXPECT_TRUE(r.has(ViolationKind::CellInconsistentOrientation)) << text(r);
}

TEST(SchemesCheck, VertexMovedOffBoundaryIsRejected) {
    auto d = load("F");
    // m = (6,0,6) lies on the leaf face y = 0 only
    const auto id = vertex_at(d, {6, 0, 6});
    for (auto& v : d.vertices)
        if (v.id == id) v.position.y = 1;
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.topology.ok()) << "a move keeps the combinatorics";
    EXPECT_TRUE(r.has(ElementIssueKind::BoundaryFaceOffLeaf)) << text(r);
    EXPECT_TRUE(message_mentions(r, ElementIssueKind::BoundaryFaceOffLeaf, "(6,1,6)")) << text(r);
    EXPECT_TRUE(r.has(ElementIssueKind::LeafFaceNotTiled)) << text(r);
}

TEST(SchemesCheck, VertexOutsideLeafIsRejected) {
    auto d = load("C1");
    d.vertices.back().position.x = 13;  // (12,12,12) -> (13,12,12)
    const auto r = check_element(d);
    EXPECT_TRUE(r.has(ElementIssueKind::VertexOutsideLeaf)) << text(r);
}

TEST(SchemesCheck, DeletedCellLeavesLeafUnfilled) {
    auto d = load("F");
    d.cells.erase(d.cells.begin() + static_cast<std::ptrdiff_t>(cell_index(d, "lid")));
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.has(ElementIssueKind::LeafUnderfilled)) << text(r);
    EXPECT_FALSE(r.has(ElementIssueKind::LeafOverfilled));
    EXPECT_TRUE(r.has(ElementIssueKind::BoundaryFaceOffLeaf)) << text(r);  // the lid's interior faces
    EXPECT_TRUE(r.has(ElementIssueKind::LeafFaceNotTiled)) << text(r);
    EXPECT_TRUE(r.has(ViolationKind::FaceUnused) || r.topology.ok()) << text(r);
}

TEST(SchemesCheck, DuplicatedCellOverfillsLeaf) {
    auto d = load("F");
    auto copy = d.cells[cell_index(d, "q")];
    copy.label = "q2";
    d.cells.push_back(copy);
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.has(ElementIssueKind::LeafOverfilled)) << text(r);
    EXPECT_TRUE(r.has(ViolationKind::DuplicateCell)) << text(r);
    EXPECT_TRUE(r.has(ViolationKind::FaceOvershared) || r.has(ViolationKind::FaceSameOrientation)) << text(r);
}

TEST(SchemesCheck, SwappedLoopVerticesAreRejected) {
    auto d = load("F");
    const auto c = cell_index(d, "p1");
    // a quad of p1: swap its 2nd and 3rd vertices (a bow tie with two foreign edges)
    auto it = std::find_if(d.cells[c].faces.begin(), d.cells[c].faces.end(),
                           [](const auto& f) { return f.size() == 4; });
    ASSERT_NE(it, d.cells[c].faces.end());
    std::swap((*it)[1], (*it)[2]);
    const auto r = check_element(d);
    EXPECT_FALSE(r.ok());
    EXPECT_TRUE(r.has(ViolationKind::CellOpenEdge)) << text(r);
    EXPECT_TRUE(message_mentions(r, ElementIssueKind::Topology, "'p1'")) << text(r);
}

TEST(SchemesCheck, InvertedCellHasNegativeVolume) {
    auto d = load("C1");
    // turn the tetrahedron inside out: every face reversed (closed and consistent, but
    // inward; its faces now meet 'rest' with equal orientation)
    for (auto& f : d.cells[cell_index(d, "tet0")].faces) std::reverse(f.begin(), f.end());
    const auto r = check_element(d);
    EXPECT_TRUE(r.has(ElementIssueKind::CellNonPositiveVolume)) << text(r);
    EXPECT_TRUE(message_mentions(r, ElementIssueKind::CellNonPositiveVolume, "'tet0'")) << text(r);
}

TEST(SchemesCheck, InteriorFaceOnLeafFaceIsRejected) {
    // a leaf of size 2 split into two slabs at z = 1; checked against a box whose +z
    // face is the split plane, the shared face lies on a leaf face.
    const std::string text_ =
        "dualhex-element 1\nname S\nleaf 2\n"
        "vertex 0 0 0 0\nvertex 1 2 0 0\nvertex 2 2 2 0\nvertex 3 0 2 0\n"
        "vertex 4 0 0 1\nvertex 5 2 0 1\nvertex 6 2 2 1\nvertex 7 0 2 1\n"
        "vertex 8 0 0 2\nvertex 9 2 0 2\nvertex 10 2 2 2\nvertex 11 0 2 2\n"
        "cell lo\nface 0 3 2 1\nface 4 5 6 7\nface 0 1 5 4\nface 2 3 7 6\nface 1 2 6 5\nface 0 4 7 3\nend\n"
        "cell hi\nface 4 7 6 5\nface 8 9 10 11\nface 4 5 9 8\nface 6 7 11 10\nface 5 6 10 9\nface 4 8 11 7\nend\n";
    const auto d = parse_element_string(text_);
    ASSERT_TRUE(check_element(d).ok()) << text(check_element(d));
    // Check with a box whose +z face is the split plane: the shared face now lies on a leaf face.
    const auto r = check_element(to_complex(d), ElementBox{{0, 0, -1}, 2});
    EXPECT_TRUE(r.has(ElementIssueKind::InteriorFaceOnLeafFace)) << text(r);
}
