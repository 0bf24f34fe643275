#pragma once
// The surface-to-hex-mesh pipeline (`dualhex mesh`, issue 7), first complete version.
//
//   surface --(AABB tree)--> octree refined at the surface (surface_octree)
//           --> least weakly/strongly balanced refinement (balance), then the least paired
//               and balanced refinement of that (pair)
//           --> elements installed (WeakRule / StrongRule), verify_installation must pass
//           --> clipped dual (exact rational dual positions, one hex per primal vertex)
//           --> embedding: lattice point p -> root.origin + root.size * p / extent,
//               extent = unit << max_level (a dual vertex: its rational centroid, mapped)
//           --> extraction: the hexes whose centroid is inside the surface (is_inside)
//           --> projection: every vertex on the kept set's boundary quads moves to its
//               closest surface point (AABB tree)
//           --> smoothing: Laplacian (mean of edge neighbours) of the interior vertices,
//               an iteration is rejected (and smoothing stops) if it increases the number
//               of inverted hexes (scaled Jacobian <= 0)
//           --> untangling: the vertices of hexes still inverted or with scaled Jacobian
//               < untangle_below are moved back half-way towards their embedded dual
//               positions (before projection and smoothing), up to `untangle_rounds`
//               times; a round is rejected (and untangling stops) if it increases the
//               number of inverted hexes, or keeps it and increases the number below the
//               threshold (trades surface distance for quality; `untangled_vertices`)
//           --> report: quality, interior singular edges, one-sided surface distance.
//
// Writing the file is the caller's job (write_hex_mesh); MeshTimes::write is left 0.
// Errors: std::invalid_argument for bad options, std::runtime_error if the installation
// does not verify or the clipped dual has a non-cube cell (a bug, never bad input).
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

namespace dualhex::geometry {

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

/// The embedded default shape: a torus (major radius 1, minor radius 0.4, 48 x 24 quads
/// split into triangles), closed and oriented outward. source = "<default torus>".
[[nodiscard]] TriangleSurface default_shape();

/// Interior edges (not an edge of a boundary quad) with a number of hexes != 4.
[[nodiscard]] std::map<int, std::size_t> interior_singular_edge_valences(const HexMesh& mesh);

/// Number of hexes with scaled Jacobian <= 0.
[[nodiscard]] std::size_t count_inverted(const HexMesh& mesh);

}  // namespace dualhex::geometry
