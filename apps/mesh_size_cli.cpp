// The size options of `dualhex mesh` (mesh_size_cli.hpp).
#include "mesh_size_cli.hpp"

#include <iostream>
#include <stdexcept>

#include "commands.hpp"
#include "dualhex/geometry/surface_octree.hpp"

namespace dualhex::app {

void add_size_options(CLI::App& sub, MeshSizeCli& cli) {
    const std::string g = "Size";
    sub.add_option("--preset", cli.preset, "coarse, medium (default) or fine: about 5k, 20k, 100k hexes on the bunny")
        ->check(CLI::IsMember({"coarse", "medium", "fine"}))
        ->group(g);
    auto* size = sub.add_option("--size", cli.size, "Target cell size at the surface, model units")->group(g);
    sub.add_option("--size-rel", cli.size_rel, "Target size as a fraction of the bbox diagonal (medium: 0.02)")
        ->excludes(size)
        ->group(g);
    sub.add_option("--surface-band", cli.surface_band,
                   "Cells within this many target sizes of the surface get the target size too (default 0)")
        ->group(g);
    sub.add_option("--min-depth", cli.min_depth, "Octree min depth (default 0)")->group(g);
    sub.add_option("--max-depth", cli.max_depth,
                   "Octree depth cap, 1.." + std::to_string(mesher::kMaxMeshDepth) + " (default 12)")
        ->group(g);
    sub.add_option("--thickness-factor", cli.thickness_factor,
                   "Cells at the surface at most this * the local thickness; 0: off (default 0.5)")
        ->group(g);
    sub.add_option("--thickness-levels", cli.thickness_levels,
                   "Thickness refines at most this many levels below the target size (default 3)")
        ->group(g);
    sub.add_option("--curvature-angle", cli.curvature_angle,
                   "Refine cells where the surface normal turns more than this (degrees; 0: off; default 40)")
        ->group(g);
    sub.add_option("--curvature-levels", cli.curvature_levels,
                   "Curvature refines at most this many levels below the target size (default 1)")
        ->group(g);
    sub.add_option("--max-leaves", cli.max_leaves, "Refuse octrees beyond this many leaves (default 2000000)")
        ->group(g);
    sub.add_option("--refine-rounds", cli.refine_rounds,
                   "Rounds of local refinement where the first core leaves the surface unresolved (default 0: off)")
        ->group(g);
    sub.add_option("--refine-distance", cli.refine_distance,
                   "Refine where the padded core and the surface are farther apart than this many target sizes (default 0.5)")
        ->group(g);
}

mesher::MeshSizeOptions resolve_size_options(const MeshSizeCli& cli) {
    mesher::MeshSizeOptions s = mesher::mesh_preset(*mesher::parse_mesh_preset(cli.preset));
    if (cli.size) {
        if (!(*cli.size > 0)) throw UsageError("--size must be > 0, got " + std::to_string(*cli.size));
        s.size = *cli.size;
        s.size_rel = 0;
    }
    if (cli.size_rel) {
        if (!(*cli.size_rel > 0)) throw UsageError("--size-rel must be > 0, got " + std::to_string(*cli.size_rel));
        s.size_rel = *cli.size_rel;
    }
    if (cli.surface_band) s.surface_band = *cli.surface_band;
    if (cli.thickness_factor) s.thickness_factor = *cli.thickness_factor;
    if (cli.thickness_levels) s.thickness_levels = *cli.thickness_levels;
    if (cli.curvature_angle) s.curvature_angle = *cli.curvature_angle;
    if (cli.curvature_levels) s.curvature_levels = *cli.curvature_levels;
    if (cli.min_depth) s.min_depth = *cli.min_depth;
    if (cli.max_depth) s.max_depth = *cli.max_depth;
    if (cli.max_leaves) s.max_leaves = *cli.max_leaves;
    if (cli.refine_rounds) s.refine_rounds = *cli.refine_rounds;
    if (cli.refine_distance) s.refine_distance = *cli.refine_distance;
    try {
        mesher::check_size_options(s);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return s;
}

void warn_if_capped(const mesher::MeshSizeOptions& s, const geometry::AabbTree& tree) {
    // The root cube the octree stage will use (mesher::octree_options keeps the default margin).
    const geometry::RootCube root = geometry::root_cube(tree.bounds(), geometry::SurfaceOctreeOptions{}.margin);
    const double size = mesher::target_size(s, tree.bounds());
    const int level = geometry::level_for_size(root, size);
    if (level > s.max_depth)
        std::cerr << "warning: size " << size << " needs depth " << level << ", capped at --max-depth " << s.max_depth
                  << ": cells at the surface will be " << root.edge(s.max_depth) << '\n';
}

}  // namespace dualhex::app
