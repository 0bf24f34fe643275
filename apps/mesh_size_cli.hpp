#pragma once
// The size options of `dualhex mesh` on the command line (--preset, --size, --size-rel,
// --surface-band, --min-depth, --max-depth, --thickness-factor, --thickness-levels,
// --curvature-angle, --curvature-levels, --max-leaves; mesher/mesh_size.hpp says what they
// do): the preset's values, overridden by each option given.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <optional>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/mesher/mesh_size.hpp"

namespace dualhex::app {

struct MeshSizeCli {
    std::string preset = "medium";
    std::optional<double> size, size_rel, surface_band, thickness_factor, curvature_angle;
    std::optional<int> min_depth, max_depth, curvature_levels, thickness_levels;
    std::optional<std::size_t> max_leaves;
    std::optional<int> refine_rounds;
    std::optional<double> refine_distance;
};

/// Adds the options (group "Size") to the mesh subcommand.
void add_size_options(CLI::App& sub, MeshSizeCli& cli);

/// The preset overridden by the options given; UsageError (exit 2) naming the option if a
/// value is out of range or the options contradict each other.
[[nodiscard]] mesher::MeshSizeOptions resolve_size_options(const MeshSizeCli& cli);

/// On stderr: a warning when the target size needs a deeper octree than --max-depth.
void warn_if_capped(const mesher::MeshSizeOptions& size, const geometry::AabbTree& tree);

}  // namespace dualhex::app
