#pragma once
// Size control of `dualhex mesh`: how fine the octree is at the surface, where it refines
// further, and the caps. The octree stage turns these into geometry::SurfaceOctreeOptions
// (surface_octree.hpp says what each criterion does).
//
//   size            target cell edge at the surface, model units (0: use size_rel)
//   size_rel        target edge as a fraction of the surface's bounding-box diagonal
//   surface_band    cells within band * (target edge) of the surface also get the target
//   min_depth       every cell at least this deep
//   max_depth       a cap only: no cell deeper (1..kMaxMeshDepth)
//   thickness_factor  cells crossing the surface at most this * the local thickness (0: off)
//   thickness_levels  thickness refines at most this many levels below the target's level
//   curvature_angle   max normal spread over a crossing cell, degrees (0: off)
//   curvature_levels  curvature refines at most this many levels below the target's level
//   max_leaves      refuse (OctreeTooLarge) an octree estimated or grown beyond this
//   refine_rounds   rounds of the refine stage (refine_unresolved.hpp; 0: off)
//   refine_distance where the mesh padded from the core and the input are farther apart
//                   than this * (target edge), the octree is split within that distance
//
// Presets, tuned on gao_bunny_tri.off to about 5k, 20k and 100k hexes (measured: 5,389,
// 24,835, 106,767; all 15 shared models in README, `dualhex mesh`): coarse (size_rel 0.04,
// thickness_factor 1, curvature_angle 50), medium (the defaults of MeshSizeOptions), fine
// (size_rel 0.01). They leave the caps and levels alone.
#include <cstddef>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "dualhex/geometry/surface_octree.hpp"

namespace dualhex::mesher {

/// Deepest octree the mesher accepts: lattice coordinates are unit << depth (int64, far
/// from overflow); the installation verifies at these depths (tested at 15 and up).
inline constexpr int kMaxMeshDepth = 16;

/// Most rounds of the refine stage (each splits the leaves around unresolved places once).
inline constexpr int kMaxRefineRounds = 8;

enum class MeshPreset { Coarse, Medium, Fine };

struct MeshSizeOptions {
    double size = 0;
    double size_rel = 0.02;
    double surface_band = 0;
    int min_depth = 0;
    int max_depth = 12;
    double thickness_factor = 0.5;
    int thickness_levels = 3;
    double curvature_angle = 40;
    int curvature_levels = 1;
    std::size_t max_leaves = 2'000'000;  ///< about 2.5 GB through the pipeline
    int refine_rounds = 0;  // off by default: see mesher/README.md, "refine"
    double refine_distance = 0.5;
};

/// The preset's values (medium == MeshSizeOptions{}).
[[nodiscard]] MeshSizeOptions mesh_preset(MeshPreset preset);
/// "coarse", "medium", "fine"; empty for anything else.
[[nodiscard]] std::optional<MeshPreset> parse_mesh_preset(const std::string& name);

/// Throws std::invalid_argument naming the option: negative size/size_rel/band/factor/angle
/// or levels, an angle above 180, both size and size_rel zero, depths outside [0, kMaxMeshDepth] (max >= 1),
/// min_depth > max_depth, max_leaves 0, refine_rounds outside [0, 8], refine_distance <= 0.
void check_size_options(const MeshSizeOptions& size);

/// The target edge at the surface in model units: size, else size_rel * bbox diagonal.
[[nodiscard]] double target_size(const MeshSizeOptions& size, const Eigen::AlignedBox3d& bbox);

/// The octree stage's options for a surface with bounding box `bbox`.
[[nodiscard]] geometry::SurfaceOctreeOptions octree_options(const MeshSizeOptions& size,
                                                            const Eigen::AlignedBox3d& bbox);

}  // namespace dualhex::mesher
