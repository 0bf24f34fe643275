#pragma once
// The surface-to-hex-mesh pipeline behind `dualhex mesh`: a sequence of named stages, each
// its own unit with documented inputs and outputs (callable on their own from the library):
//
//   stage      unit                                   in -> out
//   octree     geometry::surface_octree               surface tree -> unbalanced octree
//   balance    grid balance                           octree -> least weakly/strongly balanced refinement
//   pair       grid pair                              -> least paired and balanced refinement
//   install    install_stage.hpp install_schemes      paired grid -> installed complex (WeakRule / StrongRule)
//   verify     install_stage.hpp require_verified     must pass (a bug otherwise)
//   dual       install_stage.hpp root_clipped_dual    -> clipped dual, one hex per primal vertex (exact)
//   core       select_core.hpp select_core            -> dual hexes well inside, manifold-repaired, components
//   refine     refine_unresolved.hpp                  octree split where the core is far from the surface, then
//                                                     balance .. core again (at most refine_rounds rounds)
//   pad        pad.hpp pad_layer                      -> core + one hex layer whose outer vertices are on the surface
//   features   features.hpp snap_features             boundary vertices and edge chains -> input corners and curves,
//              feature_patches.hpp project_to_patches  then the vertices beside them onto their side's patch,
//              feature_refusal.hpp                     then snaps that invert hexes repaired or undone
//   smooth     surface_smooth.hpp, smooth.hpp         surface vertices along the surface, interior Laplacian
//   optimise   optimise.hpp optimise_mesh             untangle, then raise the minimum scaled Jacobian (roles honoured)
//   check      check_topology.hpp check_topology      boundary manifold, components and Euler = the input's;
//                                                     no inverted hex (inverted_hexes)
//   report     mesh_report.hpp, geometry quality      quality, singular edges, surface distance, creases
//
// Writing the file is the caller's job (geometry::write_hex_mesh); MeshTimes::write is left 0.
// Size control: the MeshSizeOptions part of the options (mesh_size.hpp; default the
// medium preset). A failed topology check is not an exception: result.topology says so
// (the CLI exits 1). Errors: std::invalid_argument for bad options, geometry::OctreeTooLarge
// for a size whose octree would exceed max_leaves (estimated first, before any work),
// std::runtime_error if the installation does not verify, the clipped dual has a non-cube
// cell (bugs, never bad input) or the core is empty (EmptyCoreError: no dual hex well
// inside the surface).
#include <cstddef>
#include <functional>
#include <map>
#include <vector>
#include <string>
#include <string_view>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/grid/neighbours.hpp"
#include "dualhex/mesher/default_shape.hpp"
#include "dualhex/mesher/feature_report.hpp"
#include "dualhex/mesher/features.hpp"
#include "dualhex/mesher/mesh_report.hpp"
#include "dualhex/mesher/mesh_size.hpp"
#include "dualhex/mesher/check_topology.hpp"
#include "dualhex/mesher/constrained_position.hpp"
#include "dualhex/mesher/mesh_report.hpp"
#include "dualhex/mesher/optimise.hpp"
#include "dualhex/mesher/optimise_release.hpp"
#include "dualhex/mesher/pad.hpp"
#include "dualhex/mesher/core_selection.hpp"
#include "dualhex/geometry/surface_distance.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "dualhex/topology/progress.hpp"

namespace dualhex::mesher {

using geometry::AabbTree;
using geometry::HexMesh;
using geometry::HausdorffResult;
using geometry::QualitySummary;
using geometry::RootCube;
using geometry::TriangleSurface;

/// The check stage fails a hex whose scaled Jacobian is at most this: inverted, or so flat
/// that rounding (another formula, the written file's 17 digits) may make it inverted.
inline constexpr double kFlatScaledJacobian = 1e-6;

struct MeshPipelineResult;

/// The size options (size, size_rel, min/max depth, ...: mesh_size.hpp) and the rest.
struct MeshPipelineOptions : MeshSizeOptions {
    Balance balance = Balance::Weak;
    int smooth_iterations = 5;          ///< interior Laplacian and surface smoothing iterations (each)
    /// Sharp features: normal deviation (degrees) above which an input edge is a feature
    /// (geometry/feature_curves.hpp); 0 turns the features stage off.
    double feature_angle = 45.0;
    /// Chains of feature edges shorter than this fraction of the bbox diagonal are not
    /// features (geometry::FeatureOptions::min_chain_length): on the shared surfaces the CAD
    /// models' chains are >= 0.17 of it, organic models' tessellation creases mostly < 0.1.
    double feature_min_chain = 0.1;
    FeatureSnapOptions feature_snap;    ///< how the features stage snaps (features.hpp)
    CoreOptions core;
    PadOptions pad;
    OptimiseOptions optimise;           ///< optimise.min_quality: the target minimum scaled Jacobian
    /// After the optimiser, within its stage: hexes left <= kFlatScaledJacobian freed on their
    /// region, releasing the feature roles that hold them (optimise_release.hpp).
    bool release_stuck = true;
    /// Called before each stage with its short name ("octree", "pair", ...) and the number
    /// of stages done of all of them (may be empty).
    Progress progress;
    /// Called after the moving stages ("pad", "features", "smooth", "optimise") with the
    /// result so far (mesh, constraints, core_hexes) and the quality state (may be empty;
    /// diagnostics such as pad_diagnosis.hpp).
    std::function<void(std::string_view, const MeshPipelineResult&, const QualityState&)> observe;
};

/// Milliseconds per stage. balance_pair = balance + pair: the balanced grid first, then the
/// least paired and balanced refinement of it (the same grid as pairing the octree directly).
struct MeshTimes {
    double octree = 0, balance = 0, pair = 0, balance_pair = 0, install = 0, verify = 0, dual = 0, core = 0, refine = 0, pad = 0,
           features = 0, smooth = 0, optimise = 0, check = 0, report = 0, write = 0;
};

struct MeshPipelineResult {
    HexMesh mesh;                         ///< core + pad, smoothed, optimised (VTK order)
    geometry::HexCellData cell_data;      ///< per hex of `mesh`: scaled Jacobian, octree level
    VertexConstraints constraints;        ///< (mesh points) the roles the moving stages honoured
    RootCube root;
    double target_size = 0;               ///< the size at the surface asked for (model units)
    int size_level = 0;                   ///< level of target_size, uncapped (> max_depth: capped)
    int octree_depth = 0;                 ///< deepest leaf of the octree
    std::size_t curvature_splits = 0;     ///< octree cells split for curvature alone
    std::size_t leaves = 0;               ///< paired, balanced grid
    std::size_t cells = 0;                ///< cells of the installed complex
    std::size_t dual_hexes = 0;           ///< hexes of the clipped dual (whole root cube)
    std::map<int, std::size_t> dual_edge_valences;  ///< of the whole clipped dual
    CoreSelection core;                   ///< the core stage's figures (core.mesh is moved into mesh)
    /// The refine stage (refine_unresolved.hpp): unresolved places found after each core
    /// selection it ran on, rounds that split the octree, leaves split in all.
    struct Refine {
        std::vector<std::size_t> places;
        int rounds = 0;
        std::size_t split = 0;
    } refine;
    std::size_t core_hexes = 0, pad_hexes = 0;
    std::size_t boundary_vertices = 0;    ///< on the surface (the pad's outer vertices)
    std::size_t padded_by_ray = 0, padded_by_closest_point = 0, padded_switched = 0;
    std::size_t inverted_after_pad = 0;
    /// snap_features' report, with patch_moves from project_to_patches and inverted_after
    /// after both (zeros if the stage is off).
    FeatureSnapReport features;
    /// Sharp-edge samples and creases at 0.5% of the bbox diagonal (zeros if off): of the
    /// output, and of the mesh as the features stage left it (the optimiser keeps snapped
    /// vertices on their curves and corners).
    CreaseMeasure creases, creases_snapped;
    int smooth_iterations_done = 0;       ///< accepted interior Laplacian iterations
    int surface_smooth_iterations_done = 0;
    OptimiseResult optimise;
    ReleaseResult release;                ///< the optimise stage's last step (zeros if off)
    TopologyCheck topology;
    /// Check stage: the hexes of `mesh` with scaled Jacobian <= kFlatScaledJacobian (or NaN),
    /// inverted or flat, in id order. Any is a failed check (the CLI exits 1), like a
    /// topology mismatch.
    std::vector<std::size_t> inverted_hexes;
    QualitySummary quality;
    /// Interior edges (not on a boundary quad) of the kept mesh with != 4 hexes: valence -> count.
    std::map<int, std::size_t> singular_edge_valences;
    HausdorffResult hausdorff;            ///< one-sided, sampled (the older figure)
    geometry::SurfaceDistance distance;   ///< two-sided (surface_distance.hpp)
    /// Where the input is farther than 0.6% of the bbox diagonal from the hex boundary, and
    /// which core decision left the hexes there out (mesh_report.hpp).
    std::vector<FarSurfacePoint> far_points;
    MeshTimes ms;           ///< wall time per stage
    MeshTimes cpu_ms;       ///< CPU time per stage, every thread of the process (measuring only)
    MeshTimes main_cpu_ms;  ///< CPU time per stage of the calling thread: about the wall time on free cores
};

/// Runs the pipeline on the surface of `tree` (closed, outward oriented).
[[nodiscard]] MeshPipelineResult mesh_surface(const AabbTree& tree, const MeshPipelineOptions& options = {});

}  // namespace dualhex::mesher
