#pragma once
// Stage "optimise": move vertices, under their roles, to untangle and then to raise the
// minimum scaled Jacobian.
//
// Input : the mesh (points (N, 3), hexes (M, 8) VTK order), its roles (N) and feature
//         curves (constrained_position.hpp), the surface's tree, its quality state.
// Output: the mesh with moved points (ids unchanged) and its quality state; the figures.
// Contract: the inverted count is never larger than the input's and the minimum scaled
//         Jacobian never lower (checked once on the whole result, which is otherwise
//         restored: OptimiseResult::restored); Surface vertices end on the surface (their closest point),
//         Curve vertices on their polyline, Corner vertices where they were. Bounded by
//         sweeps and by a work budget: work_per_vertex x the number of vertices visits of
//         a vertex (one gradient or candidate step each; phase 1 gets at most half), counted,
//         not timed, so the result is the same on any machine and under any load. An
//         optional wall-clock bound (time_limit_ms, off by default) is a safety net only:
//         when it is hit the result depends on the machine (hit_time_limit says so).
// Errors: std::invalid_argument from check_constraints.
//
// The phases work on the bad hexes: scaled Jacobian <= bad_below (default 0: inverted ones;
// the check's flat threshold 1e-6 adds flat ones, measured slower and worse, mesher/README.md);
// the contract is on the inverted count (<= 0) and the minimum.
// Phase 1, untangle (only if some hex is bad): the barrier energy f_eps of Garanzha et al.
// 2021 (mesher/src/hex_energy.hpp) over the 8 corner tets of every hex near a bad one
// (2 vertex rings), minimised by Gauss-Seidel sweeps of per-vertex damped Newton steps
// (the exact 3x3 Hessian, restricted to the vertex's domain, backtracking until the local
// energy decreases); a sweep visits only the vertices whose energy can have changed (a
// vertex of one of their hexes moved by > 1e-3 of the local size, or a corner det within
// 10 eps). eps starts at the paper's value and is decreased after each sweep by the paper's
// rule (energy-decrease floor 0.3, optimise_untangle.cpp says why); after 25 sweeps without
// fewer bad hexes the region grows by a ring around what is still bad (up to 4 rings, from
// the best state so far, eps restarted), then it stops; it also stops when nothing is bad.
// It returns the best state it saw (fewest bad hexes, then the highest minimum), and is
// kept only if that has fewer bad hexes, or as many and no lower a minimum.
// Phase 2, quality: sweeps over the vertices of the hexes below min_quality, worst first;
// per vertex three candidate moves (down the barrier gradient, up the numerical gradient
// of the local minimum scaled Jacobian, towards the mean of its hexes' centroids) with
// step halving; the best is taken only if it lowers the number of bad hexes at the vertex,
// or keeps it and raises their minimum scaled Jacobian. A vertex is retried only after a
// vertex of one of its hexes moved. Stops when
// the minimum reaches min_quality, a sweep moves nothing, or 10 sweeps in a row did not
// raise the minimum by 1e-4.
#include <cstddef>
#include <vector>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/constrained_position.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "dualhex/mesher/vertex_constraints.hpp"

namespace dualhex::mesher {

struct OptimiseOptions {
    double min_quality = 0.5;   ///< target minimum scaled Jacobian
    int untangle_sweeps = 200;
    int quality_sweeps = 100;
    /// Vertex visits allowed, per vertex of the mesh (0: no budget, only the sweep bounds).
    /// Deterministic. 100: the medium preset's meshes of the shared surfaces take about
    /// 1-5 s of one core here (`dualhex mesh --optimise-work`).
    double work_per_vertex = 100;
    /// Wall-clock bound in ms, checked before each vertex visit; 0 (default): none. Opt-in
    /// only: with it the output depends on the machine's speed and load.
    double time_limit_ms = 0;
    /// Hexes still inverted at the end: up to this many more runs on their region alone
    /// (optimise_region, 2, 3, 4 rings, each with this budget per region vertex), where a
    /// fresh untangling schedule often frees what the whole-mesh run stalled on.
    int rescue_rounds = 3;
    /// The phases work on hexes with scaled Jacobian <= this (or NaN). Default 0: inverted
    /// hexes only. kFlatScaledJacobian (1e-6, what the check refuses) makes them chase flat
    /// hexes too: on the CAD models that doubled the CPU and the share below 0.5 without
    /// freeing their flat hexes (mesher/README.md, measured), so it is opt-in.
    double bad_below = 0;
};

struct OptimiseResult {
    std::size_t inverted_before = 0, inverted_after = 0;
    double min_before = 0, min_after = 0;
    int untangle_sweeps = 0;      ///< done (0: nothing inverted)
    bool untangle_kept = false;   ///< phase 1 ran and was kept
    int quality_sweeps = 0;       ///< done
    std::size_t moves = 0;        ///< accepted vertex moves of phase 2
    bool reached_target = false;  ///< min_after >= min_quality
    bool restored = false;        ///< the final contract check put the start back (a phase broke it)
    std::size_t work = 0;          ///< vertex visits done (both phases)
    std::size_t work_budget = 0;   ///< allowed (0: unbounded)
    bool hit_work_budget = false;  ///< stopped by the budget (deterministic)
    bool hit_time_limit = false;   ///< stopped by time_limit_ms (machine-dependent)
};

/// The optimiser on the hexes within `rings` vertex rings of `seeds` only: they are cut out
/// as a mesh of their own whose vertices on hexes outside the region are held, so nothing
/// outside changes and the work (and the budget, per region vertex) is local. Its figures
/// are the region's.
OptimiseResult optimise_region(geometry::HexMesh& mesh, const std::vector<std::size_t>& seeds, int rings,
                               const VertexConstraints& constraints, const geometry::AabbTree& tree,
                               const FeatureCurves& curves, const OptimiseOptions& options);

OptimiseResult optimise_mesh(geometry::HexMesh& mesh, const VertexConstraints& constraints, const geometry::AabbTree& tree,
                             const FeatureCurves& curves, const OptimiseOptions& options, QualityState& state);

}  // namespace dualhex::mesher
