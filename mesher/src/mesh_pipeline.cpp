// The surface-to-hex-mesh pipeline (mesh_pipeline.hpp): the stages in order, each timed.
#include "dualhex/mesher/mesh_pipeline.hpp"

#include <chrono>
#include <stdexcept>

#include "dualhex/grid/refinement.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/install_stage.hpp"
#include "dualhex/mesher/select_core.hpp"
#include "dualhex/mesher/smooth.hpp"
#include "dualhex/mesher/surface_smooth.hpp"

namespace dualhex::mesher {
namespace {

using Clock = std::chrono::steady_clock;

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
    if (options.max_depth < 1 || options.max_depth > 12)
        throw std::invalid_argument("max depth must be in [1, 12], got " + std::to_string(options.max_depth));
    if (!(options.thickness_factor > 0)) throw std::invalid_argument("thickness factor must be > 0");
    if (!(options.core.margin >= 0)) throw std::invalid_argument("core margin must be >= 0");
    if (options.smooth_iterations < 0) throw std::invalid_argument("smoothing iterations must be >= 0");
}

// Stage "core": the dual embedded, the core chosen and its interior valences counted.
CoreSelection core_stage(const ClippedDual& dual, const InstallResult& installed, const RootCube& root,
                         const AabbTree& tree, const CoreOptions& options) {
    const EmbeddedDual embedded = embed_dual(dual, root_extent(installed), root, tree);
    CoreSelection core = select_core(dual, embedded, geometry::surface_topology(tree.surface()).size(), options);
    core.singular_edge_valences = interior_singular_edge_valences(core.mesh);
    return core;
}

// Stage "pad": result.core.mesh padded into result.mesh, with its roles and figures.
void pad_stage(MeshPipelineResult& result, const AabbTree& tree, const PadOptions& options) {
    PadResult padded = pad_layer(result.core.mesh, tree, options);
    result.core.mesh = {};
    result.mesh = std::move(padded.mesh);
    result.constraints = std::move(padded.constraints);
    result.pad_hexes = padded.pad_hexes;
    result.boundary_vertices = padded.surface_vertices;
    result.padded_by_ray = padded.by_ray;
    result.padded_by_closest_point = padded.by_closest_point;
    result.padded_switched = padded.switched;
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
    MeshTimes& ms = result.ms;

    geometry::SurfaceOctreeOptions octree_options;
    octree_options.max_depth = options.max_depth;
    octree_options.thickness_factor = options.thickness_factor;
    geometry::SurfaceOctree octree =
        timed(options, "octree", ms.octree, [&] { return geometry::surface_octree(tree, octree_options); });
    result.root = octree.root;
    const LeafGrid balanced = timed(options, "balance", ms.balance, [&] { return balance(octree.grid, options.balance); });
    const LeafGrid grid = timed(options, "pair", ms.pair, [&] { return pair(balanced, options.balance); });
    ms.balance_pair = ms.balance + ms.pair;
    result.leaves = grid.size();

    const InstallResult installed =
        timed(options, "install", ms.install, [&] { return install_schemes(grid, options.balance); });
    result.cells = installed.complex.n_cells();
    (void)timed(options, "verify", ms.verify, [&] { return require_verified(installed); });
    const ClippedDual dual = timed(options, "dual", ms.dual, [&] { return root_clipped_dual(installed); });
    result.dual_hexes = dual.hexes.size();
    result.dual_edge_valences = clipped_dual_edge_valences(dual);

    result.core = timed(options, "core", ms.core,
                        [&] { return core_stage(dual, installed, octree.root, tree, options.core); });
    if (result.core.mesh.hexes.empty())
        throw EmptyCoreError("the core is empty: no dual hex lies well inside the surface (max depth too small?)");
    result.core_hexes = result.core.mesh.hexes.size();

    QualityState state;
    timed(options, "pad", ms.pad, [&] {
        pad_stage(result, tree, options.pad);
        state = quality_state(result.mesh);
    });
    result.inverted_after_pad = state.inverted;

    const FeatureCurves curves;  // the features stage will provide them
    const VertexDomain domain{tree, curves, result.constraints};
    timed(options, "smooth", ms.smooth, [&] { smooth_stage(result, domain, options.smooth_iterations, state); });
    HexMesh& mesh = result.mesh;
    result.optimise = timed(options, "optimise", ms.optimise, [&] {
        return optimise_mesh(mesh, result.constraints, tree, curves, options.optimise, state);
    });
    result.topology = timed(options, "check", ms.check, [&] { return check_topology(mesh, tree.surface()); });

    timed(options, "report", ms.report, [&] {
        result.quality = geometry::summarize(state.scaled_jacobian);
        result.singular_edge_valences = interior_singular_edge_valences(mesh);
        result.hausdorff = geometry::boundary_to_surface_distance(mesh, tree);
        result.distance = geometry::surface_distance(mesh, tree);
    });
    return result;
}

}  // namespace dualhex::mesher
