// Exact loop tools of the variants (variant_loops.hpp).
#include "variant_loops.hpp"

#include <algorithm>
#include <map>
#include <sstream>

namespace dualhex::variants::detail {

namespace {
constexpr std::int64_t U = kLeaf;
}  // namespace

LatticePoint cross(const LatticePoint& a, const LatticePoint& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
std::int64_t dot(const LatticePoint& a, const LatticePoint& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// p strictly inside the segment ab (exact).
bool on_segment(const LatticePoint& p, const LatticePoint& a, const LatticePoint& b) {
    if (p == a || p == b) return false;
    const LatticePoint d = b - a, e = p - a;
    if (!(cross(d, e) == LatticePoint{0, 0, 0})) return false;
    const std::int64_t t = dot(e, d);
    return t > 0 && t < dot(d, d);
}

Loop insert_tjunctions(const Loop& loop, const std::set<LatticePoint>& verts) {
    Loop out;
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
        const LatticePoint& a = loop[k];
        const LatticePoint& b = loop[(k + 1) % n];
        out.push_back(a);
        std::vector<LatticePoint> mids;
        for (const auto& v : verts)
            if (on_segment(v, a, b)) mids.push_back(v);
        std::sort(mids.begin(), mids.end(), [&](const LatticePoint& u, const LatticePoint& w) {
            return dot(u - a, b - a) < dot(w - a, b - a);
        });
        out.insert(out.end(), mids.begin(), mids.end());
    }
    return out;
}

// cx.canon_face: the loop rotated to its smallest point, in the smaller direction.
Loop canonical_loop(const Loop& loop) {
    const std::size_t n = loop.size();
    const std::size_t i = static_cast<std::size_t>(std::min_element(loop.begin(), loop.end()) - loop.begin());
    Loop a(n), b(n);
    for (std::size_t k = 0; k < n; ++k) {
        a[k] = loop[(i + k) % n];
        b[k] = loop[(i + n - k) % n];
    }
    return std::min(a, b);
}

// (axis, value) of the leaf face containing the loop, or axis -1.
std::pair<int, std::int64_t> leaf_face_of(const Loop& f) {
    for (int axis = 0; axis < 3; ++axis)
        for (std::int64_t v : {std::int64_t{0}, U})
            if (std::all_of(f.begin(), f.end(), [&](const LatticePoint& p) { return p[axis] == v; })) return {axis, v};
    return {-1, 0};
}

UEdge uedge(const LatticePoint& a, const LatticePoint& b) { return a < b ? UEdge{a, b} : UEdge{b, a}; }

std::string point_string(const LatticePoint& p) {
    std::ostringstream os;
    os << p;
    return os.str();
}

// cx.orient_cell: consistent by BFS over shared edges, outward by the signed volume.
Faces orient_cell(Faces faces, const std::string& label) {
    const std::size_t n = faces.size();
    std::map<UEdge, std::vector<std::size_t>> edge_faces;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = 0; k < faces[i].size(); ++k)
            edge_faces[uedge(faces[i][k], faces[i][(k + 1) % faces[i].size()])].push_back(i);
    for (const auto& [e, fl] : edge_faces)
        if (fl.size() != 2)
            throw VariantConstructionError("cell '" + label + "': edge " + point_string(e.first) + "-" +
                                           point_string(e.second) + " in " + std::to_string(fl.size()) + " faces");
    auto has_directed = [](const Loop& f, const LatticePoint& a, const LatticePoint& b) {
        for (std::size_t k = 0; k < f.size(); ++k)
            if (f[k] == a && f[(k + 1) % f.size()] == b) return true;
        return false;
    };
    std::vector<bool> done(n, false);
    std::vector<std::size_t> stack{0};
    done[0] = true;
    while (!stack.empty()) {
        const std::size_t i = stack.back();
        stack.pop_back();
        const Loop fi = faces[i];
        for (std::size_t k = 0; k < fi.size(); ++k) {
            const LatticePoint &a = fi[k], &b = fi[(k + 1) % fi.size()];
            for (std::size_t j : edge_faces[uedge(a, b)]) {
                if (j == i || done[j]) continue;
                if (has_directed(faces[j], a, b)) std::reverse(faces[j].begin(), faces[j].end());
                done[j] = true;
                stack.push_back(j);
            }
        }
    }
    if (!std::all_of(done.begin(), done.end(), [](bool d) { return d; }))
        throw VariantConstructionError("cell '" + label + "': faces disconnected");
    std::int64_t volume6 = 0;
    for (const auto& f : faces)
        for (std::size_t k = 1; k + 1 < f.size(); ++k) volume6 += dot(f[0], cross(f[k], f[k + 1]));
    if (volume6 == 0) throw VariantConstructionError("cell '" + label + "': zero volume");
    if (volume6 < 0)
        for (auto& f : faces) std::reverse(f.begin(), f.end());
    return faces;
}

}  // namespace dualhex::variants::detail
