#include "dualhex/schemes/element_check.hpp"

#include <array>
#include <sstream>

#include "dualhex/schemes/element.hpp"

namespace dualhex {

namespace {

using Vec = std::array<std::int64_t, 3>;

Vec sub(const LatticePoint& a, const LatticePoint& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::int64_t dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Twice the area vector of a loop: fan from its first vertex.
Vec area2(const CellComplex& cx, const std::vector<VertexHandle>& loop) {
    Vec n{0, 0, 0};
    if (loop.size() < 3) return n;
    const auto& p0 = cx.position(loop[0]);
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        const auto t = cross(sub(cx.position(loop[i]), p0), sub(cx.position(loop[i + 1]), p0));
        for (int a = 0; a < 3; ++a) n[a] += t[a];
    }
    return n;
}

std::string loop_text(const CellComplex& cx, std::span<const VertexHandle> loop) {
    std::ostringstream os;
    os << '[';
    for (std::size_t i = 0; i < loop.size(); ++i) os << (i ? " " : "") << cx.position(loop[i]);
    os << ']';
    return os.str();
}

}  // namespace

const char* to_string(ElementIssueKind kind) {
    switch (kind) {
        case ElementIssueKind::Topology: return "Topology";
        case ElementIssueKind::VertexOutsideLeaf: return "VertexOutsideLeaf";
        case ElementIssueKind::BoundaryFaceOffLeaf: return "BoundaryFaceOffLeaf";
        case ElementIssueKind::BoundaryFaceInward: return "BoundaryFaceInward";
        case ElementIssueKind::InteriorFaceOnLeafFace: return "InteriorFaceOnLeafFace";
        case ElementIssueKind::LeafFaceNotTiled: return "LeafFaceNotTiled";
        case ElementIssueKind::CellNonPositiveVolume: return "CellNonPositiveVolume";
        case ElementIssueKind::LeafUnderfilled: return "LeafUnderfilled";
        case ElementIssueKind::LeafOverfilled: return "LeafOverfilled";
        case ElementIssueKind::Count: break;
    }
    return "?";
}

const char* leaf_face_name(int leaf_face) {
    static constexpr const char* names[] = {"-x", "+x", "-y", "+y", "-z", "+z"};
    return leaf_face >= 0 && leaf_face < 6 ? names[leaf_face] : "none";
}

std::size_t ElementCheckReport::count(ElementIssueKind k) const {
    std::size_t n = 0;
    for (const auto& i : issues) n += i.kind == k;
    return n;
}

void ElementCheckReport::print(std::ostream& os, std::size_t max_listed) const {
    if (ok()) {
        os << "element valid\n";
        return;
    }
    os << issues.size() << " issue(s)\n";
    for (std::size_t i = 0; i < issues.size() && i < max_listed; ++i)
        os << "  " << to_string(issues[i].kind) << ": " << issues[i].message << '\n';
    if (issues.size() > max_listed) os << "  ... " << issues.size() - max_listed << " more\n";
}

ElementCheckReport check_element(const CellComplex& cx, const ElementBox& box, const std::vector<std::string>& labels) {
    ElementCheckReport r;
    auto cell_name = [&](std::size_t c) {
        std::string s = "cell " + std::to_string(c);
        if (c < labels.size()) s += " '" + labels[c] + "'";
        return s;
    };
    auto add = [&](ElementIssueKind k, FaceHandle f, CellHandle c, int lf, std::string msg) {
        ElementIssue is;
        is.kind = k;
        is.face = f;
        is.cell = c;
        is.leaf_face = lf;
        is.message = std::move(msg);
        r.issues.push_back(std::move(is));
    };

    // (a) DESIGN.md section 4 items 1-2.
    r.topology = validate(cx, ValidationOptions{.interior_filter = {}, .check_interior = false});
    for (const auto& v : r.topology.violations) {
        ElementIssue is;
        is.kind = ElementIssueKind::Topology;
        is.violation = v.kind;
        is.face = v.face;
        is.cell = v.cell;
        std::string where;
        if (v.cell.valid()) where = cell_name(v.cell.index()) + ": ";
        if (v.face.valid()) where += "face " + std::to_string(v.face.idx) + " " + loop_text(cx, cx.face_vertices(v.face)) + ": ";
        is.message = std::string(to_string(v.kind)) + ": " + where + v.message;
        r.issues.push_back(std::move(is));
    }

    // (b) exact filling of the leaf box.
    const std::int64_t L = box.size;
    auto on_plane = [&](const LatticePoint& p, int lf) {
        const int a = lf / 2;
        return p[a] == box.min[a] + (lf % 2 ? L : 0);
    };
    for (std::size_t v = 0; v < cx.n_vertices(); ++v) {
        const auto& p = cx.position(VertexHandle(v));
        for (int a = 0; a < 3; ++a)
            if (p[a] < box.min[a] || p[a] > box.min[a] + L) {
                std::ostringstream os;
                os << "vertex " << v << " at " << p << " outside the leaf box " << box.min << " + [0," << L << "]^3";
                add(ElementIssueKind::VertexOutsideLeaf, {}, {}, -1, os.str());
                break;
            }
    }

    // Which cells use each face, and with which half-face.
    std::vector<std::vector<std::pair<CellHandle, HalfFaceHandle>>> users(cx.n_faces());
    for (std::size_t c = 0; c < cx.n_cells(); ++c)
        for (auto h : cx.cell_halffaces(CellHandle(c))) users[h.face().index()].push_back({CellHandle(c), h});

    std::array<std::int64_t, 6> tiled{};
    for (std::size_t f = 0; f < cx.n_faces(); ++f) {
        const FaceHandle fh(f);
        const auto loop = cx.face_vertices(fh);
        int plane = -1;
        for (int lf = 0; lf < 6 && plane < 0; ++lf) {
            bool all = !loop.empty();
            for (auto v : loop) all = all && on_plane(cx.position(v), lf);
            if (all) plane = lf;
        }
        if (users[f].empty()) continue;  // FaceUnused: reported by validate
        if (users[f].size() >= 2) {
            if (plane >= 0)
                add(ElementIssueKind::InteriorFaceOnLeafFace, fh, users[f][0].first, plane,
                    "face " + std::to_string(f) + " " + loop_text(cx, loop) + " shared by " +
                        std::to_string(users[f].size()) + " cells lies in the leaf face " + leaf_face_name(plane));
            continue;
        }
        const auto [cell, h] = users[f][0];
        if (plane < 0) {
            add(ElementIssueKind::BoundaryFaceOffLeaf, fh, cell, -1,
                cell_name(cell.index()) + ": boundary face " + std::to_string(f) + " " + loop_text(cx, loop) +
                    " (in no other cell) is not in any leaf-face plane");
            continue;
        }
        const auto n = area2(cx, cx.halfface_vertices(h));
        const int a = plane / 2;
        const std::int64_t outward = plane % 2 ? n[a] : -n[a];
        if (outward <= 0) {
            add(ElementIssueKind::BoundaryFaceInward, fh, cell, plane,
                cell_name(cell.index()) + ": boundary face " + std::to_string(f) + " " +
                    loop_text(cx, cx.halfface_vertices(h)) + " on leaf face " + leaf_face_name(plane) +
                    (outward == 0 ? " has zero area" : " is oriented inward (twice-area " + std::to_string(outward) + ")"));
        }
        tiled[plane] += outward;
    }
    for (int lf = 0; lf < 6; ++lf)
        if (tiled[lf] != 2 * L * L)
            add(ElementIssueKind::LeafFaceNotTiled, {}, {}, lf,
                std::string("leaf face ") + leaf_face_name(lf) + ": boundary faces cover twice-area " +
                    std::to_string(tiled[lf]) + ", expected 2*leaf^2 = " + std::to_string(2 * L * L));

    r.expected_volume6 = 6 * L * L * L;
    for (std::size_t c = 0; c < cx.n_cells(); ++c) {
        std::int64_t vol6 = 0;
        for (auto h : cx.cell_halffaces(CellHandle(c))) {
            const auto loop = cx.halfface_vertices(h);
            for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
                const auto p0 = sub(cx.position(loop[0]), box.min);
                const auto p1 = sub(cx.position(loop[i]), box.min);
                const auto p2 = sub(cx.position(loop[i + 1]), box.min);
                vol6 += dot(p0, cross(p1, p2));
            }
        }
        if (vol6 <= 0)
            add(ElementIssueKind::CellNonPositiveVolume, {}, CellHandle(c), -1,
                cell_name(c) + ": signed volume x6 = " + std::to_string(vol6) + " (must be positive)");
        r.volume6 += vol6;
    }
    if (r.volume6 < r.expected_volume6)
        add(ElementIssueKind::LeafUnderfilled, {}, {}, -1,
            "cells' volumes x6 sum to " + std::to_string(r.volume6) + " < 6*leaf^3 = " + std::to_string(r.expected_volume6) +
                ": the leaf is not filled");
    else if (r.volume6 > r.expected_volume6)
        add(ElementIssueKind::LeafOverfilled, {}, {}, -1,
            "cells' volumes x6 sum to " + std::to_string(r.volume6) + " > 6*leaf^3 = " + std::to_string(r.expected_volume6) +
                ": the leaf is overfilled");
    return r;
}

ElementCheckReport check_element(const ElementData& element) {
    std::vector<std::string> labels;
    for (const auto& c : element.cells) labels.push_back(c.label);
    return check_element(to_complex(element), ElementBox{{}, element.leaf}, labels);
}

}  // namespace dualhex
