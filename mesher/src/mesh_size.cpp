// Size options and presets of `dualhex mesh` (mesh_size.hpp).
#include "dualhex/mesher/mesh_size.hpp"

#include <numbers>
#include <stdexcept>

namespace dualhex::mesher {

MeshSizeOptions mesh_preset(MeshPreset preset) {
    MeshSizeOptions o;  // medium
    switch (preset) {
    case MeshPreset::Coarse:  // thin parts and curvature less eagerly refined too
        o.size_rel = 0.04;
        o.thickness_factor = 1.0;
        o.curvature_angle = 50;
        break;
    case MeshPreset::Medium: break;
    case MeshPreset::Fine: o.size_rel = 0.01; break;
    }
    return o;
}

std::optional<MeshPreset> parse_mesh_preset(const std::string& name) {
    if (name == "coarse") return MeshPreset::Coarse;
    if (name == "medium") return MeshPreset::Medium;
    if (name == "fine") return MeshPreset::Fine;
    return std::nullopt;
}

void check_size_options(const MeshSizeOptions& o) {
    auto refuse = [](const std::string& what) { throw std::invalid_argument(what); };
    if (!(o.size >= 0)) refuse("size must be > 0, got " + std::to_string(o.size));
    if (!(o.size_rel >= 0)) refuse("relative size must be > 0, got " + std::to_string(o.size_rel));
    if (o.size == 0 && o.size_rel == 0) refuse("size and relative size are both 0");
    if (!(o.surface_band >= 0)) refuse("surface band must be >= 0");
    if (!(o.thickness_factor >= 0)) refuse("thickness factor must be >= 0");
    if (!(o.curvature_angle >= 0 && o.curvature_angle <= 180)) refuse("curvature angle must be in [0, 180] degrees");
    if (o.curvature_levels < 0) refuse("curvature levels must be >= 0");
    if (o.thickness_levels < 0) refuse("thickness levels must be >= 0");
    if (o.max_depth < 1 || o.max_depth > kMaxMeshDepth)
        refuse("max depth must be in [1, " + std::to_string(kMaxMeshDepth) + "], got " + std::to_string(o.max_depth));
    if (o.min_depth < 0 || o.min_depth > o.max_depth)
        refuse("min depth must be in [0, max depth " + std::to_string(o.max_depth) + "], got " +
               std::to_string(o.min_depth));
    if (o.max_leaves == 0) refuse("max leaves must be > 0");
    if (o.refine_rounds < 0 || o.refine_rounds > kMaxRefineRounds)
        refuse("refine rounds must be in [0, " + std::to_string(kMaxRefineRounds) + "], got " +
               std::to_string(o.refine_rounds));
    if (!(o.refine_distance > 0)) refuse("refine distance must be > 0, got " + std::to_string(o.refine_distance));
}

double target_size(const MeshSizeOptions& o, const Eigen::AlignedBox3d& bbox) {
    return o.size > 0 ? o.size : o.size_rel * bbox.diagonal().norm();
}

geometry::SurfaceOctreeOptions octree_options(const MeshSizeOptions& o, const Eigen::AlignedBox3d& bbox) {
    geometry::SurfaceOctreeOptions g;
    g.max_depth = o.max_depth;
    g.min_depth = o.min_depth;
    g.thickness_factor = o.thickness_factor;
    g.surface_size = target_size(o, bbox);
    g.surface_band = o.surface_band * g.surface_size;
    g.curvature_angle = o.curvature_angle * std::numbers::pi / 180.0;
    g.curvature_levels = o.curvature_levels;
    g.thickness_levels = o.thickness_levels;
    g.max_leaves = o.max_leaves;
    return g;
}

}  // namespace dualhex::mesher
