// Exact self-intersection search. Why the tests suffice: the intersection of two closed
// triangles is convex; if not empty, its extreme points lie on an edge of one triangle
// inside the other, so "some edge of one meets the other" decides it. With one shared
// vertex v, a second common point exists iff the edge opposite v in one triangle meets the
// other; with a shared edge, iff the triangles are coplanar and on the same side of it.
#include "dualhex/geometry/self_intersection.hpp"

#include <algorithm>
#include <sstream>

#include "exact_predicates.hpp"

namespace dualhex::geometry {

namespace {

using P = Eigen::Vector3d;
using Tri = std::array<P, 3>;

// Two axes (u, v) onto which a plane projects one-to-one.
struct Plane2 {
    int u = 0, v = 1;
    [[nodiscard]] int orient(const P& a, const P& b, const P& c) const {
        return exact::orient2d(a[u], a[v], b[u], b[v], c[u], c[v]);
    }
};

bool degenerate(const Tri& t) {
    for (int drop = 0; drop < 3; ++drop)
        if (Plane2{(drop + 1) % 3, (drop + 2) % 3}.orient(t[0], t[1], t[2]) != 0) return false;
    return true;
}

// A projection under which the (non-degenerate) triangle keeps its area.
Plane2 projection_of(const Tri& t) {
    for (int drop = 2; drop >= 0; --drop) {
        const Plane2 p{(drop + 1) % 3, (drop + 2) % 3};
        if (p.orient(t[0], t[1], t[2]) != 0) return p;
    }
    return {};  // unreachable for a non-degenerate triangle
}

// x is known collinear with segment pq: is it between them?
bool within(const Plane2& pl, const P& p, const P& q, const P& x) {
    for (int a : {pl.u, pl.v})
        if (x[a] < std::min(p[a], q[a]) || x[a] > std::max(p[a], q[a])) return false;
    return true;
}

bool segments_meet_2d(const Plane2& pl, const P& p, const P& q, const P& r, const P& s) {
    const int o1 = pl.orient(p, q, r), o2 = pl.orient(p, q, s), o3 = pl.orient(r, s, p), o4 = pl.orient(r, s, q);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && within(pl, p, q, r)) || (o2 == 0 && within(pl, p, q, s)) || (o3 == 0 && within(pl, r, s, p)) ||
           (o4 == 0 && within(pl, r, s, q));
}

bool point_in_triangle_2d(const Plane2& pl, const P& x, const Tri& t) {
    const int s = pl.orient(t[0], t[1], t[2]);
    for (int e = 0; e < 3; ++e)
        if (pl.orient(t[e], t[(e + 1) % 3], x) * s < 0) return false;
    return true;
}

// Closed segment pq against the closed, non-degenerate triangle t.
bool segment_meets_triangle(const P& p, const P& q, const Tri& t) {
    const int op = exact::orient3d(t[0], t[1], t[2], p), oq = exact::orient3d(t[0], t[1], t[2], q);
    if (op * oq > 0) return false;
    if (op == 0 && oq == 0) {  // in the triangle's plane
        const Plane2 pl = projection_of(t);
        if (point_in_triangle_2d(pl, p, t) || point_in_triangle_2d(pl, q, t)) return true;
        for (int e = 0; e < 3; ++e)
            if (segments_meet_2d(pl, p, q, t[e], t[(e + 1) % 3])) return true;
        return false;
    }
    // pq reaches the plane at one point: inside iff the line pq passes no edge on the far side.
    const int s1 = exact::orient3d(p, q, t[0], t[1]), s2 = exact::orient3d(p, q, t[1], t[2]),
              s3 = exact::orient3d(p, q, t[2], t[0]);
    return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

// Corner lists rotated so that the `shared` common vertices come first, in the same order.
struct Aligned {
    int shared = 0;
    std::array<int, 3> a{}, b{};
};

Aligned align(std::array<int, 3> a, std::array<int, 3> b) {
    Aligned out;
    std::array<int, 3> ra{}, rb{};
    int n = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                ra[n] = a[i];
                rb[n] = b[j];
                ++n;
            }
    auto rest = [&](const std::array<int, 3>& t, std::array<int, 3>& r) {
        int k = n;
        for (int c : t)
            if (std::find(r.begin(), r.begin() + n, c) == r.begin() + n) r[k++] = c;
    };
    rest(a, ra);
    rest(b, rb);
    return {n, ra, rb};
}

bool improper(const TriangleSurface& s, int ta, int tb) {
    const Aligned al = align(s.triangles[ta], s.triangles[tb]);
    auto pts = [&](const std::array<int, 3>& ids) { return Tri{s.vertices[ids[0]], s.vertices[ids[1]], s.vertices[ids[2]]}; };
    const Tri a = pts(al.a), b = pts(al.b);
    switch (al.shared) {
    case 0: return triangles_intersect(a, b);
    case 1: return segment_meets_triangle(a[1], a[2], b) || segment_meets_triangle(b[1], b[2], a);
    case 2: {
        if (exact::orient3d(a[0], a[1], a[2], b[2]) != 0) return false;
        const Plane2 pl = projection_of(a);
        return pl.orient(a[0], a[1], a[2]) * pl.orient(a[0], a[1], b[2]) > 0;
    }
    default: return true;  // the same three vertices
    }
}

// Candidate pairs by sort and sweep over the triangles' bounding boxes: boxes of doubles
// compare exactly (min/max round nothing), so no pair that touches can be missed. (The AABB
// tree's triangles_in_box was the first choice; its floating-point triangle-box test took
// two thirds of the time and needed padded boxes to stay conservative.)
struct BoxSweep {
    struct Entry {
        Eigen::AlignedBox3d box;
        int triangle;
    };
    std::vector<Entry> sorted;  // by box.min()[axis], contiguous for the scan
    int axis = 0;               // the longest extent of the whole surface: fewest overlaps

    explicit BoxSweep(const TriangleSurface& s) {
        sorted.resize(s.triangles.size());
        Eigen::AlignedBox3d all;
        for (std::size_t t = 0; t < s.triangles.size(); ++t) {
            sorted[t].triangle = static_cast<int>(t);
            for (int c : s.triangles[t]) sorted[t].box.extend(s.vertices[c]);
            all.extend(sorted[t].box);
        }
        if (!sorted.empty()) all.diagonal().maxCoeff(&axis);
        std::sort(sorted.begin(), sorted.end(),
                  [&](const Entry& a, const Entry& b) { return a.box.min()[axis] < b.box.min()[axis]; });
    }
    // Calls visit(a, b) for every pair of boxes that share a point until it returns false;
    // returns false if more than `budget` boxes were scanned (not every pair was visited).
    template <class Visit>
    bool pairs(std::size_t budget, Visit&& visit) const {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (std::size_t i = 0; i < sorted.size(); ++i) {
            const auto& bi = sorted[i].box;
            for (std::size_t j = i + 1; j < sorted.size() && sorted[j].box.min()[axis] <= bi.max()[axis]; ++j) {
                if (budget-- == 0) return false;
                const auto& bj = sorted[j].box;
                if (bj.min()[u] <= bi.max()[u] && bi.min()[u] <= bj.max()[u] && bj.min()[v] <= bi.max()[v] &&
                    bi.min()[v] <= bj.max()[v] && !visit(sorted[i].triangle, sorted[j].triangle))
                    return true;
            }
        }
        return true;
    }
};

void list_triangle(std::ostringstream& os, const TriangleSurface& s, int t) {
    const auto& v = s.triangles[t];
    os << t << " (vertices " << v[0] << ' ' << v[1] << ' ' << v[2] << ')';
}

}  // namespace

bool triangles_intersect(const Tri& a, const Tri& b) {
    for (int e = 0; e < 3; ++e)
        if (segment_meets_triangle(a[e], a[(e + 1) % 3], b) || segment_meets_triangle(b[e], b[(e + 1) % 3], a))
            return true;
    return false;
}

SelfIntersections find_self_intersections(const TriangleSurface& s, std::size_t max_listed, std::size_t stop_after,
                                          std::size_t max_candidates) {
    SelfIntersections out;
    auto corners = [&](int t) {
        const auto& v = s.triangles[static_cast<std::size_t>(t)];
        return Tri{s.vertices[v[0]], s.vertices[v[1]], s.vertices[v[2]]};
    };
    const int n = static_cast<int>(s.triangles.size());
    for (int t = 0; t < n; ++t)
        if (degenerate(corners(t)) && out.degenerate_count++ < max_listed) out.degenerate.push_back(t);
    if (out.degenerate_count > 0 || n == 0) return out;  // the pair tests need proper triangles

    const std::size_t budget = max_candidates > 0 ? max_candidates : 50'000'000 + 200 * static_cast<std::size_t>(n);
    const bool complete = BoxSweep(s).pairs(budget, [&](int a, int b) {
        if (!improper(s, std::min(a, b), std::max(a, b))) return true;
        if (out.pair_count++ < max_listed) out.pairs.push_back({std::min(a, b), std::max(a, b)});
        out.stopped_early = out.pair_count >= stop_after;
        return !out.stopped_early;
    });
    out.gave_up = !complete;
    return out;
}

std::string SelfIntersections::describe(const TriangleSurface& s) const {
    std::ostringstream os;
    if (gave_up && degenerate_count == 0 && pair_count == 0)
        return "self-intersection check gave up: far too many triangles with overlapping bounding boxes";
    if (degenerate_count > 0) {
        os << degenerate_count << " degenerate triangle" << (degenerate_count == 1 ? "" : "s")
           << " (collinear corners), e.g. ";
        for (std::size_t i = 0; i < degenerate.size(); ++i) {
            if (i > 0) os << ", ";
            list_triangle(os, s, degenerate[i]);
        }
        if (degenerate_count > degenerate.size()) os << ", ...";
        return os.str();
    }
    os << (stopped_early ? "at least " : "") << pair_count << " pair" << (pair_count == 1 ? "" : "s")
       << " of intersecting triangles, e.g. ";
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        os << (i > 0 ? ", " : "");
        list_triangle(os, s, pairs[i][0]);
        os << " x ";
        list_triangle(os, s, pairs[i][1]);
    }
    if (pair_count > pairs.size()) os << ", ...";
    return os.str();
}

}  // namespace dualhex::geometry
