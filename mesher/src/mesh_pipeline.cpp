// The surface-to-hex-mesh pipeline (mesh_pipeline.hpp): the stages in order, each timed.
#include "dualhex/mesher/mesh_pipeline.hpp"

#include <chrono>
#include <stdexcept>

#include "dualhex/grid/refinement.hpp"
#include "dualhex/mesher/cell_levels.hpp"
#include "dualhex/mesher/extract.hpp"
#include "dualhex/mesher/feature_patches.hpp"
#include "dualhex/mesher/feature_restore.hpp"
#include "dualhex/mesher/install_stage.hpp"
#include "dualhex/mesher/project.hpp"
#include "dualhex/mesher/smooth.hpp"
#include "dualhex/mesher/untangle.hpp"

namespace dualhex::mesher {
namespace {

using Clock = std::chrono::steady_clock;

// A snapped vertex goes back to its feature only if no hex around it falls below this
// (or falls further if already below): the report's quality bar, so the share of hexes
// below 0.2 does not grow for the creases' sake.
constexpr double kRestoreBelow = 0.2;

// Runs one named stage: reports its name, times it into `ms`, returns what it returns.
template <class Stage>
auto timed(const MeshPipelineOptions& options, const char* name, double& ms, Stage&& stage) {
    if (options.progress) options.progress(name);
    const auto t0 = Clock::now();
    struct Stop {
        Clock::time_point t0;
        double& ms;
        ~Stop() { ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }
    } stop{t0, ms};
    return stage();
}

void check_options(const MeshPipelineOptions& options) {
    check_size_options(options);
    if (options.smooth_iterations < 0) throw std::invalid_argument("smoothing iterations must be >= 0");
    if (!(options.feature_angle >= 0 && options.feature_angle < 180))
        throw std::invalid_argument("feature angle must be 0 (off) or in (0, 180) degrees");
}

}  // namespace

MeshPipelineResult mesh_surface(const AabbTree& tree, const MeshPipelineOptions& options) {
    check_options(options);
    MeshPipelineResult result;
    MeshTimes& ms = result.ms;

    const geometry::SurfaceOctreeOptions octree_options = mesher::octree_options(options, tree.bounds());
    geometry::SurfaceOctree octree =
        timed(options, "octree", ms.octree, [&] { return geometry::surface_octree(tree, octree_options); });
    result.root = octree.root;
    result.target_size = octree_options.surface_size;
    result.size_level = octree.size_level;
    result.octree_depth = octree.grid.max_level();
    result.curvature_splits = octree.curvature_splits;
    const LeafGrid balanced = timed(options, "balance", ms.balance, [&] { return balance(octree.grid, options.balance); });
    const LeafGrid grid = timed(options, "pair", ms.pair, [&] { return pair(balanced, options.balance); });
    ms.balance_pair = ms.balance + ms.pair;
    result.leaves = grid.size();
    if (grid.size() > options.max_leaves)  // pairing and balance grade the octree: bounded, but check
        throw geometry::OctreeTooLarge("paired grid: " + std::to_string(grid.size()) + " leaves, more than the limit " +
                                           std::to_string(options.max_leaves),
                                       grid.size());

    const InstallResult installed =
        timed(options, "install", ms.install, [&] { return install_schemes(grid, options.balance); });
    result.cells = installed.complex.n_cells();
    (void)timed(options, "verify", ms.verify, [&] { return require_verified(installed); });
    const ClippedDual dual = timed(options, "dual", ms.dual, [&] { return root_clipped_dual(installed); });
    result.dual_hexes = dual.hexes.size();
    result.dual_edge_valences = clipped_dual_edge_valences(dual);

    HexMesh& mesh = result.mesh;
    std::vector<std::uint32_t> kept;
    mesh = timed(options, "extract", ms.extract,
                 [&] { return extract_inside(dual, root_extent(installed), octree.root, tree, &kept); });
    const std::vector<int> dual_levels = dual_hex_levels(dual, installed, grid);
    for (std::uint32_t h : kept) result.cell_data.level.push_back(dual_levels[h]);
    if (mesh.hexes.empty()) throw std::runtime_error("no hex centroid inside the surface (max depth too small?)");

    QualityState state;
    BoundaryProjection projection = timed(options, "project", ms.project, [&] {
        BoundaryProjection p = project_boundary(mesh, tree);
        state = quality_state(mesh);
        return p;
    });
    result.boundary_vertices = projection.boundary_vertices;
    result.inverted_after_projection = state.inverted;
    geometry::FeatureSet features;
    HexMesh snapped;  // the mesh as the features stage left it, measured in the report
    VertexConstraints constraints;
    timed(options, "features", ms.features, [&] {
        if (options.feature_angle <= 0) return;
        geometry::FeatureOptions feature_options;
        feature_options.angle_degrees = options.feature_angle;
        features = geometry::detect_features(tree.surface(), feature_options);
        result.features = snap_features(mesh, features, constraints);
        result.features.patch_moves =
            project_to_patches(mesh, tree, features, constraints, result.features.path_edges);
        state = quality_state(mesh);
        result.features.inverted_after = state.inverted;
        snapped.points = mesh.points;
    });
    result.smooth_iterations_done = timed(options, "smooth", ms.smooth, [&] {
        return smooth_interior(mesh, projection.on_boundary, options.smooth_iterations, state);
    });
    result.untangled_vertices = timed(options, "untangle", ms.untangle, [&] {
        return untangle_towards(mesh, projection.unprojected, options.untangle_rounds, options.untangle_below, state);
    });

    result.restored_vertices = timed(options, "restore", ms.restore, [&] {
        if (options.feature_angle <= 0) return std::size_t{0};
        return restore_features(mesh, snapped.points, constraints, kRestoreBelow, options.untangle_rounds,
                                state);
    });

    timed(options, "report", ms.report, [&] {
        result.quality = geometry::summarize(state.scaled_jacobian);
        result.cell_data.scaled_jacobian = state.scaled_jacobian;
        result.singular_edge_valences = interior_singular_edge_valences(mesh);
        result.hausdorff = geometry::boundary_to_surface_distance(mesh, tree);
        if (options.feature_angle > 0) {
            result.creases = measure_creases(mesh, tree.surface(), features, options.feature_angle);
            snapped.hexes = mesh.hexes;
            result.creases_snapped = measure_creases(snapped, tree.surface(), features, options.feature_angle);
        }
    });
    return result;
}

}  // namespace dualhex::mesher
