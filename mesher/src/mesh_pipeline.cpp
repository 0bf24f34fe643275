// The surface-to-hex-mesh pipeline (mesh_pipeline.hpp): the stages in order, each timed.
#include "dualhex/mesher/mesh_pipeline.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <map>
#include <stdexcept>
#include <string_view>

#include "dualhex/grid/refinement.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/cpu_clock.hpp"
#include "dualhex/mesher/cell_levels.hpp"
#include "dualhex/mesher/core_boundary_smooth.hpp"
#include "dualhex/mesher/feature_patches.hpp"
#include "dualhex/mesher/feature_refusal.hpp"
#include "dualhex/mesher/install_stage.hpp"
#include "dualhex/mesher/refine_unresolved.hpp"
#include "dualhex/mesher/select_core.hpp"
#include "dualhex/mesher/smooth.hpp"
#include "dualhex/mesher/surface_smooth.hpp"

namespace dualhex::mesher {
namespace {

using Clock = std::chrono::steady_clock;

// The Hausdorff target of issue 12 (relative to the bbox diagonal): farther surface points
// are listed with their cause (far_surface_points).
constexpr double kFarSurfaceDistance = 0.006;

// The stages in run order: progress reports stage i as i of their number done (a stage
// missing here reports all done: add new stages to the list).
constexpr std::array<std::string_view, 14> kStages{"octree", "balance",  "pair",   "install",  "verify", "dual",   "core",
                                                   "refine", "pad",      "features", "smooth", "optimise", "check", "report"};

// Runs one named stage: reports its name, times it into result's `field` of ms (wall),
// cpu_ms (all threads) and main_cpu_ms (this thread), returns what it returns.
template <class Stage>
auto timed(const MeshPipelineOptions& options, std::string_view name, MeshPipelineResult& result,
           double MeshTimes::*field, Stage&& stage) {
    if (options.progress) {
        const auto i = static_cast<std::size_t>(std::find(kStages.begin(), kStages.end(), name) - kStages.begin());
        options.progress(name, i, kStages.size());
    }
    struct Stop {
        MeshPipelineResult& result;
        double MeshTimes::*field;
        Clock::time_point t0 = Clock::now();
        double cpu0 = process_cpu_ms(), main0 = thread_cpu_ms();
        ~Stop() {  // summed over rounds
            result.ms.*field += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            result.cpu_ms.*field += process_cpu_ms() - cpu0;
            result.main_cpu_ms.*field += thread_cpu_ms() - main0;
        }
    } stop{result, field};
    return stage();
}

void observe(const MeshPipelineOptions& options, std::string_view stage, const MeshPipelineResult& result,
             const QualityState& state) {
    if (options.observe) options.observe(stage, result, state);
}

void check_options(const MeshPipelineOptions& options) {
    check_size_options(options);
    if (!(options.core.margin >= 0)) throw std::invalid_argument("core margin must be >= 0");
    if (options.smooth_iterations < 0) throw std::invalid_argument("smoothing iterations must be >= 0");
    if (!(options.feature_angle >= 0 && options.feature_angle < 180))
        throw std::invalid_argument("feature angle must be 0 (off) or in (0, 180) degrees");
    if (!(options.feature_min_chain >= 0)) throw std::invalid_argument("feature chain length must be >= 0");
}

// The feature curves as the moving stages take them: closed iff the first point is
// repeated at the end (constrained_position.hpp), indexed as snap_features' curve ids.
FeatureCurves moving_stage_curves(const geometry::FeatureSet& features) {
    FeatureCurves out;
    for (const geometry::FeatureCurve& c : features.curves) {
        out.push_back(c.points);
        if (c.closed && !c.points.empty()) out.back().push_back(c.points.front());
    }
    return out;
}

// Per hex of the padded mesh: its octree level. A core hex has its dual hex's level; a pad
// hex (one per core boundary quad, after the core hexes) the level of the core hex whose
// face it grows from, found by the quad's sorted vertex ids.
std::vector<int> padded_levels(const HexMesh& padded, std::size_t core_hexes, const std::vector<int>& core_levels) {
    std::vector<int> out(core_levels.begin(), core_levels.end());
    std::map<std::array<int, 4>, int> face_level;
    for (std::size_t h = 0; h < core_hexes; ++h)
        for (const auto& f : geometry::kHexFaces) {
            std::array<int, 4> key{};
            for (std::size_t i = 0; i < 4; ++i) key[i] = padded.hexes[h][static_cast<std::size_t>(f[i])];
            std::sort(key.begin(), key.end());
            face_level.emplace(key, core_levels[h]);
        }
    for (std::size_t h = core_hexes; h < padded.hexes.size(); ++h) {
        std::array<int, 4> key{padded.hexes[h][0], padded.hexes[h][1], padded.hexes[h][2], padded.hexes[h][3]};
        std::sort(key.begin(), key.end());
        const auto it = face_level.find(key);
        out.push_back(it == face_level.end() ? -1 : it->second);
    }
    return out;
}

// Stages "balance" and "pair": the least paired and balanced refinement of the octree.
LeafGrid grid_stages(const MeshPipelineOptions& options, const LeafGrid& octree, MeshPipelineResult& result) {
    const LeafGrid balanced =
        timed(options, "balance", result, &MeshTimes::balance, [&] { return balance(octree, options.balance); });
    LeafGrid grid = timed(options, "pair", result, &MeshTimes::pair, [&] { return pair(balanced, options.balance); });
    for (MeshTimes* t : {&result.ms, &result.cpu_ms, &result.main_cpu_ms}) t->balance_pair = t->balance + t->pair;
    if (grid.size() > options.max_leaves)  // pairing and balance grade the octree: bounded, but check
        throw geometry::OctreeTooLarge("paired grid: " + std::to_string(grid.size()) + " leaves, more than the limit " +
                                           std::to_string(options.max_leaves),
                                       grid.size());
    return grid;
}

// Stage "core": the dual embedded, the core chosen and its interior valences counted.
CoreSelection core_stage(const ClippedDual& dual, const InstallResult& installed, const RootCube& root,
                         const AabbTree& tree, const CoreOptions& options) {
    const EmbeddedDual embedded = embed_dual(dual, root_extent(installed), root, tree);
    CoreSelection core = select_core(dual, embedded, geometry::surface_topology(tree.surface()), options, true);
    if (options.cleanup) clean_core_selection(dual, embedded, options, core);  // before the pad: core_cleanup.hpp
    core.singular_edge_valences = interior_singular_edge_valences(core.mesh);
    return core;
}

// The pad stage's work on `core`: its boundary smoothed (if asked), then padded.
PadResult pad_core(HexMesh core, const AabbTree& tree, const PadOptions& options) {
    (void)smooth_core_boundary(core, options.core_smoothing, options.core_smoothing_floor);
    return pad_layer(core, tree, options);
}

// Stage "pad": result.core.mesh padded into result.mesh, with its roles and figures.
void pad_stage(MeshPipelineResult& result, const AabbTree& tree, const PadOptions& options) {
    PadResult padded = pad_core(std::move(result.core.mesh), tree, options);
    result.core.mesh = {};
    result.mesh = std::move(padded.mesh);
    result.constraints = std::move(padded.constraints);
    result.pad_hexes = padded.pad_hexes;
    result.boundary_vertices = padded.surface_vertices;
    result.padded_by_ray = padded.by_ray;
    result.padded_by_closest_point = padded.by_closest_point;
    result.padded_switched = padded.switched;
}

// Stage "refine": the octree split around the places the core leaves unresolved (those
// where the mesh it pads to is far from the surface); false when there is none, nothing
// was split or the split octree would exceed max_leaves (then the octree and the core stay
// as they are).
bool refine_stage(MeshPipelineResult& result, LeafGrid& octree, const AabbTree& tree,
                  const MeshPipelineOptions& options) {
    const double far = options.refine_distance * result.target_size;
    const HexMesh padded = result.core.mesh.hexes.empty() ? HexMesh{} : pad_core(result.core.mesh, tree, options.pad).mesh;
    const std::vector<UnresolvedPlace> places = unresolved_places(padded, tree, far);
    result.refine.places.push_back(places.size());
    if (places.empty()) return false;
    LocalRefinement refined = refine_at_places(octree, result.root, places, options.max_depth, far);
    if (refined.split == 0 || refined.grid.size() > options.max_leaves) return false;
    octree = std::move(refined.grid);
    result.refine.split += refined.split;
    ++result.refine.rounds;
    return true;
}

// Stage "smooth": surface vertices along the surface, then the interior Laplacian.
void smooth_stage(MeshPipelineResult& result, const VertexDomain& domain, int iterations, QualityState& state) {
    result.surface_smooth_iterations_done = smooth_surface(result.mesh, domain, iterations, state);
    std::vector<char> fixed(result.mesh.points.size());
    for (std::size_t v = 0; v < fixed.size(); ++v) fixed[v] = result.constraints.role[v] != VertexRole::Interior;
    result.smooth_iterations_done = smooth_interior(result.mesh, fixed, iterations, state);
}

}  // namespace

MeshPipelineResult mesh_surface(const AabbTree& tree, const MeshPipelineOptions& options) {
    check_options(options);
    MeshPipelineResult result;

    const geometry::SurfaceOctreeOptions octree_options = mesher::octree_options(options, tree.bounds());
    geometry::SurfaceOctree octree =
        timed(options, "octree", result, &MeshTimes::octree, [&] { return geometry::surface_octree(tree, octree_options); });
    result.root = octree.root;
    result.target_size = octree_options.surface_size;
    result.size_level = octree.size_level;
    result.curvature_splits = octree.curvature_splits;
    // Stages balance .. core on the octree; then "refine" splits it where the core leaves the
    // surface unresolved and they run again (at most refine_rounds times).
    LeafGrid octree_grid = std::move(octree.grid);
    LeafGrid grid;
    InstallResult installed;
    ClippedDual dual;
    for (int round = 0;; ++round) {
        grid = grid_stages(options, octree_grid, result);
        result.leaves = grid.size();
        installed = timed(options, "install", result, &MeshTimes::install, [&] { return install_schemes(grid, options.balance); });
        result.cells = installed.complex.n_cells();
        (void)timed(options, "verify", result, &MeshTimes::verify, [&] { return require_verified(installed); });
        dual = timed(options, "dual", result, &MeshTimes::dual, [&] { return root_clipped_dual(installed); });
        result.core = timed(options, "core", result, &MeshTimes::core,
                            [&] { return core_stage(dual, installed, octree.root, tree, options.core); });
        if (round == options.refine_rounds) break;
        const bool again = timed(options, "refine", result, &MeshTimes::refine, [&] {
            return refine_stage(result, octree_grid, tree, options);
        });
        if (!again) break;
    }
    result.octree_depth = octree_grid.max_level();
    result.dual_hexes = dual.hexes.size();
    result.dual_edge_valences = clipped_dual_edge_valences(dual);
    if (result.core.mesh.hexes.empty())
        throw EmptyCoreError("the core is empty: no dual hex lies well inside the surface (max depth too small?)");
    result.core_hexes = result.core.mesh.hexes.size();
    std::vector<int> core_levels;
    {
        const std::vector<int> dual_levels = dual_hex_levels(dual, installed, grid);
        for (std::uint32_t h : result.core.dual_hex) core_levels.push_back(dual_levels[h]);
    }

    QualityState state;
    timed(options, "pad", result, &MeshTimes::pad, [&] {
        pad_stage(result, tree, options.pad);
        state = quality_state(result.mesh);
    });
    result.inverted_after_pad = state.inverted;
    observe(options, "pad", result, state);
    result.cell_data.level = padded_levels(result.mesh, result.core_hexes, core_levels);

    geometry::FeatureSet features;
    FeatureCurves curves;
    HexMesh snapped;  // the mesh as the features stage left it, measured in the report
    timed(options, "features", result, &MeshTimes::features, [&] {
        if (options.feature_angle <= 0) return;
        geometry::FeatureOptions feature_options;
        feature_options.angle_degrees = options.feature_angle;
        feature_options.min_chain_length = options.feature_min_chain * tree.bounds().diagonal().norm();
        features = geometry::detect_features(tree.surface(), feature_options);
        curves = moving_stage_curves(features);
        const std::vector<Eigen::Vector3d> before = result.mesh.points;
        const std::vector<double> sj_before = state.scaled_jacobian;
        result.features = snap_features(result.mesh, features, result.constraints, options.feature_snap);
        result.features.patch_moves =
            project_to_patches(result.mesh, tree, features, result.constraints, result.features.path_edges);
        state = quality_state(result.mesh);
        // The stage hands on no hex it inverted: repaired around the snap, or the snap undone.
        refuse_inverting_snaps(result.mesh, before, sj_before, result.constraints, result.features, tree, curves,
                               state);
        result.features.inverted_after = state.inverted;
        snapped.points = result.mesh.points;
    });
    observe(options, "features", result, state);
    const VertexDomain domain{tree, curves, result.constraints};
    timed(options, "smooth", result, &MeshTimes::smooth, [&] { smooth_stage(result, domain, options.smooth_iterations, state); });
    observe(options, "smooth", result, state);
    HexMesh& mesh = result.mesh;
    result.optimise = timed(options, "optimise", result, &MeshTimes::optimise, [&] {
        OptimiseResult r = optimise_mesh(mesh, result.constraints, tree, curves, options.optimise, state);
        if (options.release_stuck)
            result.release = release_stuck_hexes(mesh, result.constraints, tree, curves, options.optimise, state,
                                                 kFlatScaledJacobian);
        return r;
    });
    observe(options, "optimise", result, state);
    result.topology = timed(options, "check", result, &MeshTimes::check, [&] {
        result.inverted_hexes.clear();  // never success for an inverted mesh
        for (std::size_t h = 0; h < state.scaled_jacobian.size(); ++h)
            if (!(state.scaled_jacobian[h] > kFlatScaledJacobian)) result.inverted_hexes.push_back(h);
        return check_topology(mesh, tree.surface());
    });

    timed(options, "report", result, &MeshTimes::report, [&] {
        result.quality = geometry::summarize(state.scaled_jacobian);
        result.cell_data.scaled_jacobian = state.scaled_jacobian;
        result.singular_edge_valences = interior_singular_edge_valences(mesh);
        result.hausdorff = geometry::boundary_to_surface_distance(mesh, tree);
        result.distance = geometry::surface_distance(mesh, tree);
        result.far_points = far_surface_points(mesh, tree, result.core, kFarSurfaceDistance * result.distance.diagonal);
        if (options.feature_angle > 0) {
            result.creases = measure_creases(mesh, tree.surface(), features, options.feature_angle);
            snapped.hexes = mesh.hexes;
            result.creases_snapped = measure_creases(snapped, tree.surface(), features, options.feature_angle);
        }
    });
    return result;
}

}  // namespace dualhex::mesher
