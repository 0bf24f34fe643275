#pragma once
// Repair of a cell selection whose boundary is not a 2-manifold (issue 12, part 6).
//
// Stage  : after extraction (which cells are inside), before projection.
// Input  : cells    — (M, 8) vertex ids (VTK_HEXAHEDRON order) of ALL cells of a
//                     conforming all-hex complex, selected or not (the repair needs the
//                     cells around a defect to choose from); ids in [0, vertex_count);
//          selected — (M) 0/1, the cells kept (e.g. centroid inside the surface);
//          score    — (M) finite doubles, > 0 where the cell belongs inside, < 0 where it
//                     belongs outside (e.g. the signed distance of its centre, or its
//                     inside fraction - 1/2); used to pick the geometrically better side.
// Output : ManifoldRepairResult — the new selection (M), every change in the order made,
//          and the defects that remain at the end (boundary_defects of the selected
//          cells: empty iff the boundary is a manifold). Defects that cannot be repaired
//          are reported there, never hidden.
// Errors : std::invalid_argument for size mismatches, ids out of range, a non-finite score.
//
// A defect spot is a non-manifold edge of the selection's boundary (in != 2 boundary
// quads, e.g. the 4 cells around an edge selected in a diagonal pattern) or a
// non-manifold vertex (the selected cells around it do not form one solid with a disk
// boundary there), exactly as boundary_defects (hex_topology.hpp) defines them. Its star:
// the cells containing the edge or vertex.
//
// Each round computes the defects of the current selection and visits the spots in a
// fixed order (edges by ids, then vertices by id), skipping a spot whose star already
// changed in this round. At a spot one cell changes:
// - score phase (the first `score_rounds` rounds): the cheapest of adding an unselected
//   star cell (cost -score) or removing a selected one (cost +score; only if may_remove);
//   ties: adding first, then the smaller cell index. A changed cell is frozen (never
//   changed again in this phase), so this phase makes at most M changes;
// - fill phase (afterwards, or once a score round changes nothing): add the unselected
//   star cell of largest score. The selection only grows, so this terminates; in a
//   complex whose full union has a manifold boundary it ends manifold (a defect spot
//   always has an unselected star cell, and all cells selected is manifold).
// Rounds stop at a manifold selection, when a fill round changes nothing, or after
// max_rounds rounds (result.hit_round_limit).
#include <array>
#include <cstddef>
#include <vector>

#include "dualhex/geometry/hex_topology.hpp"

namespace dualhex::geometry {

struct ManifoldRepairOptions {
    int score_rounds = 32;
    int max_rounds = 100000;
    bool may_remove = true;  ///< false: cells are only ever added
};

enum class DefectSpot { Edge, Vertex };

struct SelectionChange {
    std::size_t cell = 0;
    bool selected = false;  ///< the cell's new state
    int round = 0;          ///< 0-based
    DefectSpot spot = DefectSpot::Edge;
    std::array<int, 2> at{-1, -1};  ///< the edge's vertex ids, or the vertex id and -1
};

struct ManifoldRepairResult {
    std::vector<char> selected;
    std::vector<SelectionChange> changes;
    BoundaryDefects remaining;  ///< of the final selection
    int rounds = 0;
    bool hit_round_limit = false;
    [[nodiscard]] bool manifold() const { return remaining.manifold(); }
};

[[nodiscard]] ManifoldRepairResult repair_manifold_selection(const std::vector<std::array<int, 8>>& cells,
                                                             std::size_t vertex_count, std::vector<char> selected,
                                                             const std::vector<double>& score,
                                                             const ManifoldRepairOptions& options = {});

}  // namespace dualhex::geometry
