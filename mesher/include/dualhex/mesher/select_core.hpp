#pragma once
// Stage "select core": the dual hexes that lie well inside the surface, repaired to a
// selection with a closed 2-manifold boundary, restricted to as many face-connected
// components as the input surface has. The pad stage then fills the gap between the
// core and the surface with one layer of hexes (pad.hpp).
//
// Rule (why: the pad layer needs room). Per dual point p: its signed distance s(p) to
// the surface (> 0 inside; |s| = closest-point distance, sign by is_inside). Per dual
// hex: h = the mean of its 12 edge lengths, score = min over its 8 corners of s - margin * h.
// A hex is selected iff score > 0: all 8 corners inside, at least margin * h from the
// surface, so every pad hex is at least margin * h thick (margin = 0.1 by default: a
// pad hex's height lies in about [0.1 h, 1.1 h + the rest of the gap]; a larger margin
// gives thicker pad hexes but drops thin parts of the solid, whose missing core then
// changes the topology — 0.1 with the pipeline's thickness factor 0.25 kept the topology
// on more of the shared models than 0.3 with 0.5). The same score drives manifold_repair (geometry/manifold_repair.hpp), so
// the repair adds the hexes closest to qualifying and removes the least inside ones.
//
// Components: face-connected classes of the repaired selection, by decreasing size. The
// largest `input_components` are kept (the number of components of the input surface);
// the others are dropped and listed in CoreSelection::dropped_components (never
// silently). A dropped or merged component makes the final topology check fail, which
// is where a mismatch is reported with locations.
//
// Input : the clipped dual over [0, extent]^3 (one hex per primal vertex, VTK order),
//         the root cube it maps to, the surface's tree, the input surface's component
//         count (>= 1).
// Output: CoreSelection — the core as a HexMesh (points renumbered in first-use order:
//         ids are exact dual ids remapped, no coordinate comparison), and what the
//         repair and the component filter did.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/mesher/core_selection.hpp"
#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex::mesher {

/// Signed distance (> 0 inside) of every embedded dual point; the points (N, 3) as embedded.
/// Exact inside and wherever the surface is within 4 x the point's longest dual edge;
/// farther outside, minus that bound (the search stops there: such points only ever belong
/// to hexes far outside, and the bound is all the sign spreading needs).
/// The sign is is_inside's at one point per region and spread exactly along dual edges
/// shorter than the distance (no surface between), so few points cast rays.
struct EmbeddedDual {
    std::vector<Eigen::Vector3d> points;  ///< (dual points)
    std::vector<double> signed_distance;  ///< (dual points)
};
[[nodiscard]] EmbeddedDual embed_dual(const ClippedDual& dual, std::int64_t extent, const geometry::RootCube& root,
                                      const geometry::AabbTree& tree);

[[nodiscard]] CoreSelection select_core(const ClippedDual& dual, const EmbeddedDual& embedded,
                                        std::size_t input_components, const CoreOptions& options = {});
/// The same, given the input surface's components (surface_topology); with
/// control_topology, a selection whose boundary differs from the input's topology is grown
/// again by topology-controlled steps (core_topology.hpp) and that is taken if it matches.
[[nodiscard]] CoreSelection select_core(const ClippedDual& dual, const EmbeddedDual& embedded,
                                        const std::vector<geometry::SurfaceComponent>& input,
                                        const CoreOptions& options, bool control_topology);

/// The core cleanup (core_cleanup.hpp) applied to a selection `core` made by select_core from
/// the same dual: the exposed hexes flipped where that keeps the topology, the mesh, dual_hex
/// and fates updated; if the cleaned core's boundary has other components or Euler
/// characteristics or is less manifold than before (the flips rule it out; checked), the
/// core stays as it was and cleanup_reverted is set. Does nothing for an empty core.
void clean_core_selection(const ClippedDual& dual, const EmbeddedDual& embedded, const CoreOptions& options,
                          CoreSelection& core);

/// Face-connected components of `hexes` (ids in [0, vertex_count)): per hex its component
/// index, components numbered by decreasing size (ties: smallest first hex first).
[[nodiscard]] std::vector<int> hex_face_components(const std::vector<std::array<int, 8>>& hexes,
                                                   std::size_t vertex_count);

}  // namespace dualhex::mesher
