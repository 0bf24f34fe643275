#pragma once
// Degenerate and intersecting triangles of a surface, decided exactly.
//
// Input : a TriangleSurface (indices valid).
// Output: the degenerate triangles (three collinear corners) and the pairs of triangles
//         that intersect improperly. Two closed triangles may share what their indices
//         share and nothing else: triangles with one common vertex may meet only at that
//         vertex; with a common edge only along it (so coplanar folds onto the same side
//         count); without common vertices not at all. Two triangles with the same three
//         vertices always count.
// Every decision is a sign of an exact orientation predicate (exact_predicates.hpp): no
// tolerance. Candidates are the pairs whose bounding boxes overlap (exact comparisons of
// doubles), found by sort and sweep along x.
#include <cstddef>
#include <string>
#include <vector>

#include "dualhex/geometry/surface.hpp"

namespace dualhex::geometry {

struct SelfIntersections {
    std::vector<int> degenerate;                 ///< triangle ids, at most max_listed
    std::size_t degenerate_count = 0;
    std::vector<std::array<int, 2>> pairs;       ///< (a, b) with a < b, at most max_listed
    std::size_t pair_count = 0;                  ///< pairs found (the search stops at stop_after)
    bool stopped_early = false;
    /// The candidate pairs exceeded the budget (bounding boxes overlapping far more than
    /// on any sane surface, e.g. thousands of triangles around one vertex): not decided.
    bool gave_up = false;
    [[nodiscard]] bool empty() const { return degenerate_count == 0 && pair_count == 0 && !gave_up; }
    /// "2 pairs of intersecting triangles, e.g. 3 (v 0 1 2) x 17 (v 5 6 7), ..."
    [[nodiscard]] std::string describe(const TriangleSurface& s) const;
};

/// Finds degenerate triangles, then (only if there are none) intersecting pairs; lists the
/// first `max_listed` of each and stops searching after `stop_after` pairs, or (gave_up)
/// after scanning `max_candidates` boxes (0: 5e7 + 200 F), so hostile input cannot make
/// it quadratic.
[[nodiscard]] SelfIntersections find_self_intersections(const TriangleSurface& s, std::size_t max_listed = 5,
                                                        std::size_t stop_after = 1000, std::size_t max_candidates = 0);

/// True iff the closed triangles (a0 a1 a2) and (b0 b1 b2) share a point (exact).
/// Precondition: neither is degenerate.
[[nodiscard]] bool triangles_intersect(const std::array<Eigen::Vector3d, 3>& a, const std::array<Eigen::Vector3d, 3>& b);

}  // namespace dualhex::geometry
