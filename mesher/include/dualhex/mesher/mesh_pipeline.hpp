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
//   extract    extract.hpp extract_inside             -> embedded hexes whose centroid is inside
//   project    project.hpp project_boundary           boundary quads' vertices -> closest surface points
//   smooth     smooth.hpp smooth_interior             Laplacian of interior vertices, never more inverted
//   untangle   untangle.hpp untangle_towards          bad hexes' vertices pulled back towards the dual
//   report     mesh_report.hpp, geometry quality      quality, singular edges, surface distance
//
// Writing the file is the caller's job (geometry::write_hex_mesh); MeshTimes::write is left 0.
// Errors: std::invalid_argument for bad options, std::runtime_error if the installation
// does not verify, the clipped dual has a non-cube cell (bugs, never bad input) or no hex
// centroid is inside the surface.
#include <cstddef>
#include <functional>
#include <map>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/grid/neighbours.hpp"
#include "dualhex/mesher/default_shape.hpp"
#include "dualhex/mesher/mesh_report.hpp"
#include "dualhex/mesher/quality_state.hpp"

namespace dualhex::mesher {

using geometry::AabbTree;
using geometry::HexMesh;
using geometry::HausdorffResult;
using geometry::QualitySummary;
using geometry::RootCube;
using geometry::TriangleSurface;

struct MeshPipelineOptions {
    Balance balance = Balance::Weak;
    int max_depth = 6;
    int smooth_iterations = 5;
    int untangle_rounds = 10;
    double untangle_below = 0.05;
    /// Called with a short stage name ("octree", "pair", ...) before each stage (may be empty).
    std::function<void(const std::string&)> progress;
};

/// Milliseconds per stage. balance_pair = balance + pair: the balanced grid first, then the
/// least paired and balanced refinement of it (the same grid as pairing the octree directly).
struct MeshTimes {
    double octree = 0, balance = 0, pair = 0, balance_pair = 0, install = 0, verify = 0, dual = 0, extract = 0,
           project = 0, smooth = 0, untangle = 0, report = 0, write = 0;
};

struct MeshPipelineResult {
    HexMesh mesh;                         ///< the kept, projected, smoothed hexes (VTK order)
    RootCube root;
    std::size_t leaves = 0;               ///< paired, balanced grid
    std::size_t cells = 0;                ///< cells of the installed complex
    std::size_t dual_hexes = 0;           ///< hexes of the clipped dual (whole root cube)
    std::map<int, std::size_t> dual_edge_valences;  ///< of the whole clipped dual
    std::size_t boundary_vertices = 0;    ///< projected vertices
    std::size_t inverted_after_projection = 0;
    int smooth_iterations_done = 0;       ///< accepted Laplacian iterations
    std::size_t untangled_vertices = 0;   ///< vertex moves back (sum over rounds)
    QualitySummary quality;
    /// Interior edges (not on a boundary quad) of the kept mesh with != 4 hexes: valence -> count.
    std::map<int, std::size_t> singular_edge_valences;
    HausdorffResult hausdorff;
    MeshTimes ms;
};

/// Runs the pipeline on the surface of `tree` (closed, outward oriented).
[[nodiscard]] MeshPipelineResult mesh_surface(const AabbTree& tree, const MeshPipelineOptions& options = {});

}  // namespace dualhex::mesher
