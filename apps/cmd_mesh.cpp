// dualhex mesh [INPUT] -o OUT: a closed triangle surface (OBJ/OFF/STL/PLY; none: the
// embedded default torus) to an all-hex mesh, through the octree, pairing + balancing,
// element installation, the clipped dual, the core (dual hexes well inside, repaired to a
// manifold), one pad layer onto the surface, smoothing, the optimiser and the topology
// check (mesher/mesh_pipeline.hpp). Writes OUT by extension (.vtk, .vtu, .mesh) and
// reports quality, topology and times. Exit 1 if the boundary's topology differs from the
// input's (the mesh is still written, to look at), unless --accept-topology-change.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "histogram_format.hpp"
#include "mesh_size_cli.hpp"
#include "progress_bar.hpp"
#include "threads_option.hpp"

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/cpu_clock.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::app {
namespace {

struct MeshOptionsCli {
    std::string input, output, balance = "weak";
    int smooth = 5;
    int threads = 0;  // 0: every core
    double feature_angle = 45.0;
    double min_quality = 0.5, core_margin = 0.1, core_fill_margin = 0.02, optimise_ms = 0, pad_ray_limit = 2.0;
    double optimise_work = mesher::OptimiseOptions{}.work_per_vertex;
    double feature_min_chain = mesher::MeshPipelineOptions{}.feature_min_chain;
    bool json = false, force = false, accept_topology_change = false, no_progress = false, no_release = false, path_rule = false;
    MeshSizeCli size;  // --preset, --size, ... (mesh_size_cli.hpp)
};

nlohmann::json times_json(const mesher::MeshTimes& t) {
    return {{"octree", t.octree},   {"balance", t.balance}, {"pair", t.pair},         {"balance_pair", t.balance_pair},
            {"install", t.install}, {"verify", t.verify},   {"dual", t.dual},         {"core", t.core},
            {"refine", t.refine},   {"pad", t.pad},         {"features", t.features}, {"smooth", t.smooth},
            {"optimise", t.optimise}, {"check", t.check},   {"report", t.report},     {"write", t.write}};
}

// The far surface points (mesh_report.hpp): where, how far (relative), why.
nlohmann::json far_points_json(const mesher::MeshPipelineResult& r, double diagonal) {
    nlohmann::json out = nlohmann::json::array();
    for (const mesher::FarSurfacePoint& f : r.far_points) {
        nlohmann::json fates;
        for (std::size_t i = 0; i < mesher::kCoreFates; ++i)
            if (f.fates[i] > 0) fates[mesher::core_fate_name(static_cast<mesher::CoreFate>(i))] = f.fates[i];
        out.push_back({{"point", {f.point.x(), f.point.y(), f.point.z()}},
                       {"side", f.on_hex_boundary ? "hex_boundary" : "input"},
                       {"distance", diagonal > 0 ? f.distance / diagonal : 0},
                       {"cause", mesher::core_fate_name(f.cause)},
                       {"dual_hexes", fates}});
    }
    return out;
}

void run_mesh(const MeshOptionsCli& opt) {
    const ThreadLimit limit(opt.threads);
    const mesher::MeshSizeOptions size = resolve_size_options(opt.size);
    {  // before any work: the format and the overwrite check
        const std::string ext = std::filesystem::path(opt.output).extension().string();
        if (ext != ".vtk" && ext != ".vtu" && ext != ".mesh")
            throw UsageError("output '" + opt.output + "': unknown format (use .vtk, .vtu or .mesh)");
        check_output(opt.output, opt.force);
    }
    ProgressBar bar = ProgressBar::for_stderr(opt.json, opt.no_progress);
    const std::string input_name = opt.input.empty() ? "<default torus>" : opt.input;

    geometry::TriangleSurface surface;
    geometry::SurfaceReport report;
    try {
        surface = opt.input.empty() ? mesher::default_shape() : geometry::read_surface(opt.input, {}, &report);
    } catch (const geometry::SurfaceError& e) {  // what() names the file
        std::cerr << "error: " << e.what() << '\n';
        throw Exit{kInputError};
    }
    // Always on stderr (also under --json and without a terminal); each names its file.
    for (const auto& w : report.warnings) std::cerr << "warning: " << w << '\n';
    const std::size_t triangles = surface.triangles.size();
    const geometry::AabbTree tree(std::move(surface));

    mesher::MeshPipelineOptions options;
    static_cast<mesher::MeshSizeOptions&>(options) = size;
    options.balance = opt.balance == "strong" ? Balance::Strong : Balance::Weak;
    options.smooth_iterations = opt.smooth;
    options.feature_angle = opt.feature_angle;
    options.feature_min_chain = opt.feature_min_chain;
    options.optimise.work_per_vertex = opt.optimise_work;
    options.optimise.min_quality = opt.min_quality;
    options.core.margin = opt.core_margin;
    options.core.fill_margin = opt.core_fill_margin;
    options.optimise.time_limit_ms = opt.optimise_ms;
    options.pad.ray_limit = opt.pad_ray_limit;
    options.release_stuck = !opt.no_release;
    options.feature_snap.one_edge_per_quad = opt.path_rule;
    // The pipeline's stages, then writing the file: "[mesh 11/14: optimise] 71% ...".
    std::size_t steps = 1;  // the pipeline's stages and writing the file
    const auto step = [&bar, &steps](std::string_view stage, std::size_t done) {
        bar.update("mesh " + std::to_string(done + 1) + "/" + std::to_string(steps) + ": " + std::string(stage), done, steps);
    };
    if (bar.active())
        options.progress = [&](std::string_view stage, std::size_t done, std::size_t total) {
            steps = total + 1;
            step(stage, done);
        };
    warn_if_capped(size, tree);
    mesher::MeshPipelineResult r;
    try {
        r = mesher::mesh_surface(tree, options);
    } catch (const mesher::EmptyCoreError& e) {
        bar.clear();
        std::cerr << "error: " << input_name << ": " << e.what() << '\n';
        throw Exit{kInputError};
    } catch (const geometry::OctreeTooLarge& e) {
        throw UsageError(std::string(e.what()) + " (a coarser --size or --size-rel, or raise --max-leaves)");
    }

    step("write", steps - 1);
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = mesher::process_cpu_ms(), main0 = mesher::thread_cpu_ms();
    geometry::write_hex_mesh(opt.output, r.mesh, opt.force, r.cell_data);
    r.ms.write = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    r.cpu_ms.write = mesher::process_cpu_ms() - cpu0;
    r.main_cpu_ms.write = mesher::thread_cpu_ms() - main0;
    bar.finish("mesh: " + with_commas(r.mesh.hexes.size()) + " hexes written to " +
               std::filesystem::path(opt.output).filename().string());

    const auto& q = r.quality;
    const auto& t = r.topology;
    const auto& d = r.distance;
    if (opt.json) {
        print_json({{"input", input_name},
                    {"output", opt.output},
                    {"balance", opt.balance},
                    {"max_depth", size.max_depth},
                    {"size",
                     {{"preset", opt.size.preset},
                      {"target", r.target_size},
                      {"size_level", r.size_level},
                      {"octree_depth", r.octree_depth},
                      {"min_depth", size.min_depth},
                      {"thickness_factor", size.thickness_factor},
                      {"curvature_angle", size.curvature_angle},
                      {"curvature_levels", size.curvature_levels},
                      {"curvature_splits", r.curvature_splits},
                      {"thickness_levels", size.thickness_levels},
                      {"surface_band", size.surface_band},
                      {"refine",
                       {{"rounds_asked", size.refine_rounds},
                        {"distance", size.refine_distance},
                        {"places", r.refine.places},
                        {"rounds", r.refine.rounds},
                        {"split", r.refine.split}}}}},
                    {"triangles", triangles},
                    {"warnings", report.warnings},
                    {"leaves", r.leaves},
                    {"cells", r.cells},
                    {"dual_hexes", r.dual_hexes},
                    {"hexes", r.mesh.hexes.size()},
                    {"vertices", r.mesh.points.size()},
                    {"core_hexes", r.core_hexes},
                    {"pad_hexes", r.pad_hexes},
                    {"boundary_vertices", r.boundary_vertices},
                    {"features",
                     {{"angle", opt.feature_angle},
                      {"corners", r.features.corners},
                      {"corners_snapped", r.features.corners_snapped},
                      {"curves", r.features.curves},
                      {"curves_snapped", r.features.curves_snapped},
                      {"curve_vertices", r.features.curve_vertices},
                      {"quad_turns", r.features.quad_turns},
                      {"patch_moves", r.features.patch_moves},
                      {"min_chain", opt.feature_min_chain},
                      {"inverted_by_snap", r.features.inverted_by_snap},
                      {"repaired", r.features.repaired},
                      {"curve_vertices_undone", r.features.curve_vertices_undone},
                      {"corners_undone", r.features.corners_undone},
                      {"vertices_restored", r.features.vertices_restored},
                      {"inverted_before", r.features.inverted_before},
                      {"inverted_after", r.features.inverted_after},
                      {"sharp_samples", r.creases.samples},
                      {"sharp_samples_kept", r.creases.samples_kept},
                      {"sharp_samples_kept_after_snap", r.creases_snapped.samples_kept},
                      {"crease_edges", r.creases.crease_edges},
                      {"spurious_creases", r.creases.spurious_creases},
                      {"crease_edges_after_snap", r.creases_snapped.crease_edges},
                      {"spurious_creases_after_snap", r.creases_snapped.spurious_creases}}},
                    {"core",
                     {{"selected_by_rule", r.core.selected_by_rule},
                      {"repair_added", r.core.repair_added},
                      {"repair_removed", r.core.repair_removed},
                      {"repair_manifold", r.core.repair_manifold},
                      {"kept_components", r.core.kept_components},
                      {"dropped_components", r.core.dropped_components},
                      {"rule_euler", r.core.rule_euler},
                      {"topology_controlled", r.core.topology_controlled},
                      {"topology_dropped", r.core.topology_dropped},
                      {"topology_fill", r.core.topology_fill},
                      {"topology_rejoined", r.core.topology_rejoined},
                      {"cleanup_removed", r.core.cleanup_removed},
                      {"cleanup_added", r.core.cleanup_added},
                      {"cleanup_refused", r.core.cleanup_refused},
                      {"cleanup_reverted", r.core.cleanup_reverted}}},
                    {"far_surface_points", far_points_json(r, d.diagonal)},
                    {"pad",
                     {{"by_ray", r.padded_by_ray},
                      {"by_closest_point", r.padded_by_closest_point},
                      {"switched", r.padded_switched}}},
                    {"inverted_after_pad", r.inverted_after_pad},
                    {"smooth_iterations", r.smooth_iterations_done},
                    {"surface_smooth_iterations", r.surface_smooth_iterations_done},
                    {"optimise",
                     {{"min_quality", opt.min_quality},
                      {"inverted_before", r.optimise.inverted_before},
                      {"inverted_after", r.optimise.inverted_after},
                      {"min_before", r.optimise.min_before},
                      {"min_after", r.optimise.min_after},
                      {"untangle_sweeps", r.optimise.untangle_sweeps},
                      {"untangle_kept", r.optimise.untangle_kept},
                      {"quality_sweeps", r.optimise.quality_sweeps},
                      {"moves", r.optimise.moves},
                      {"reached_target", r.optimise.reached_target},
                      {"work", r.optimise.work},
                      {"work_budget", r.optimise.work_budget},
                      {"hit_work_budget", r.optimise.hit_work_budget},
                      {"hit_time_limit", r.optimise.hit_time_limit}}},
                    {"release",
                     {{"bad_before", r.release.bad_before},
                      {"bad_after", r.release.bad_after},
                      {"curves_released", r.release.curves_released},
                      {"corners_released", r.release.corners_released},
                      {"work", r.release.work},
                      {"places_restored", r.release.places_restored}}},
                    {"inverted_hexes", r.inverted_hexes.size()},
                    {"topology",
                     {{"manifold", t.manifold},
                      {"non_manifold_edges", t.non_manifold_edges},
                      {"non_manifold_vertices", t.non_manifold_vertices},
                      {"components", t.components()},
                      {"euler", t.euler},
                      {"input_components", t.input_components()},
                      {"input_euler", t.input_euler},
                      {"hex_components", t.hex_components},
                      {"matches", t.matches},
                      {"problems", t.problems}}},
                    {"surface_distance",
                     {{"mean", d.relative(d.mean())},
                      {"max", d.relative(d.max())},
                      {"mesh_to_surface_max", d.relative(d.mesh_to_surface.max)},
                      {"surface_to_mesh_max", d.relative(d.surface_to_mesh.max)},
                      {"mesh_to_surface_farthest",
                       {d.mesh_to_surface.farthest.x(), d.mesh_to_surface.farthest.y(), d.mesh_to_surface.farthest.z()}},
                      {"surface_to_mesh_farthest",
                       {d.surface_to_mesh.farthest.x(), d.surface_to_mesh.farthest.y(), d.surface_to_mesh.farthest.z()}},
                      {"on_surface", d.share_vertices_on_surface}}},
                    {"scaled_jacobian",
                     {{"min", q.min}, {"mean", q.mean}, {"below_0", q.share_negative}, {"below_0_2", q.share_below_02}}},
                    {"singular_edge_valences", histogram_json(r.singular_edge_valences)},
                    {"core_singular_edge_valences", histogram_json(r.core.singular_edge_valences)},
                    {"hausdorff", r.hausdorff.max},
                    {"hausdorff_mean", r.hausdorff.mean},
                    {"ms", times_json(r.ms)},
                    {"cpu_ms", {{"all", times_json(r.cpu_ms)}, {"main", times_json(r.main_cpu_ms)}}}});
    } else {
        std::printf("%s: %zu triangles, %s balance\n", input_name.c_str(), triangles, opt.balance.c_str());
        std::printf("size:             %.4g at the surface (%s preset; level %d), octree depth %d (max %d)\n",
                    r.target_size, opt.size.preset.c_str(), r.size_level, r.octree_depth, size.max_depth);
        std::printf("grid:             %zu leaves, %zu installed cells, %zu dual hexes\n", r.leaves, r.cells,
                    r.dual_hexes);
        std::printf("mesh:             %zu hexes (%zu core, %zu pad), %zu vertices (%zu on the surface)\n",
                    r.mesh.hexes.size(), r.core_hexes, r.pad_hexes, r.mesh.points.size(), r.boundary_vertices);
        std::printf("scaled Jacobian:  min %.4f, mean %.4f, < 0: %.4f%%, < 0.2: %.4f%%\n", q.min, q.mean,
                    100 * q.share_negative, 100 * q.share_below_02);
        if (opt.feature_angle > 0)
            std::printf("features:         %zu/%zu corners, %zu/%zu curves snapped (%zu curve vertices, %zu moved "
                        "to their patch); inverted %zu -> %zu (%zu by the snap: %zu repaired, %zu corners and %zu "
                        "curve vertices undone); sharp-edge samples within 0.5%% of a crease: %.1f%% "
                        "(%.1f%% after snapping); %zu/%zu creases spurious\n",
                        r.features.corners_snapped, r.features.corners, r.features.curves_snapped, r.features.curves,
                        r.features.curve_vertices, r.features.patch_moves, r.features.inverted_before, r.features.inverted_after,
                        r.features.inverted_by_snap, r.features.repaired, r.features.corners_undone,
                        r.features.curve_vertices_undone,
                        100 * r.creases.kept_share(), 100 * r.creases_snapped.kept_share(), r.creases.spurious_creases,
                        r.creases.crease_edges);
        std::printf("optimise:         min %.4f -> %.4f, inverted %zu -> %zu (target %.2f %s); %zu vertex visits "
                    "of %zu%s%s\n",
                    r.optimise.min_before, r.optimise.min_after, r.optimise.inverted_before, r.optimise.inverted_after,
                    opt.min_quality, r.optimise.reached_target ? "reached" : "not reached", r.optimise.work,
                    r.optimise.work_budget, r.optimise.hit_work_budget ? " (budget spent)" : "",
                    r.optimise.hit_time_limit ? " (STOPPED by --optimise-ms: machine-dependent)" : "");
        std::printf("topology:         %s; %zu boundary components (input %zu)%s\n",
                    t.manifold ? "manifold" : "NOT manifold", t.components(), t.input_components(),
                    t.matches ? ", matches the input" : ", DIFFERS from the input");
        for (const auto& p : t.problems) std::printf("  %s\n", p.c_str());
        std::printf("singular edges:   %s (interior, valence: count); core interior: %s\n",
                    histogram_text(r.singular_edge_valences).c_str(),
                    histogram_text(r.core.singular_edge_valences).c_str());
        std::printf("surface distance: two-sided mean %.3g, max %.3g (of the bbox diagonal); %.2f%% vertices on it\n",
                    d.relative(d.mean()), d.relative(d.max()), 100 * d.share_vertices_on_surface);
        std::printf("time (ms):        octree %.1f, balance+pair %.1f, install %.1f, verify %.1f, dual %.1f, "
                    "core %.1f, pad %.1f, features %.1f, smooth %.1f, optimise %.1f, check %.1f, report %.1f, "
                    "write %.1f\n",
                    r.ms.octree, r.ms.balance_pair, r.ms.install, r.ms.verify, r.ms.dual, r.ms.core, r.ms.pad,
                    r.ms.features, r.ms.smooth, r.ms.optimise, r.ms.check, r.ms.report, r.ms.write);
        std::printf("wrote %s\n", opt.output.c_str());
    }
    if (!r.inverted_hexes.empty()) {  // no flag accepts this: an inverted hex is never a success
        std::cerr << "error: " << input_name << ": " << r.inverted_hexes.size() << " inverted or flat hex(es) (scaled Jacobian <= "
                  << mesher::kFlatScaledJacobian << ")";
        for (std::size_t i = 0; i < std::min<std::size_t>(5, r.inverted_hexes.size()); ++i) {
            const std::size_t h = r.inverted_hexes[i];
            Eigen::Vector3d c = Eigen::Vector3d::Zero();
            for (int v : r.mesh.hexes[h]) c += r.mesh.points[static_cast<std::size_t>(v)] / 8.0;
            std::cerr << (i ? "; " : ": ") << "hex " << h << " at (" << c.x() << ", " << c.y() << ", " << c.z() << ")";
        }
        std::cerr << (r.inverted_hexes.size() > 5 ? "; ..." : "") << " (the mesh is written, to look at)\n";
        throw Exit{kCheckFailed};
    }
    if (!t.matches && !opt.accept_topology_change) {
        std::cerr << "error: " << input_name << ": the mesh's boundary topology differs from the input's";
        for (const auto& p : t.problems) std::cerr << "; " << p;
        std::cerr << " (pass --accept-topology-change to accept)\n";
        throw Exit{kCheckFailed};
    }
}

}  // namespace

void register_mesh(CLI::App& app) {
    auto opt = std::make_shared<MeshOptionsCli>();
    CLI::App* sub = app.add_subcommand(
        "mesh", "Mesh a closed triangle surface (OBJ/OFF/STL/PLY; default: a torus) with hexahedra: octree, "
                "balance + pair, install, clipped dual, core, pad layer, smooth, optimise, topology check; write OUT "
                "(.vtk, .vtu or .mesh)");
    sub->add_option("input", opt->input, "Surface file (closed, manifold); omitted: the embedded torus");
    sub->add_option("-o,--output", opt->output, "Output hex mesh (.vtk, .vtu or .mesh)")->required();
    sub->add_flag("--force", opt->force, "Overwrite the output file if it exists");
    sub->add_option("--balance", opt->balance, "weak (default, weak rule) or strong (strong rule)")
        ->check(CLI::IsMember({"weak", "strong"}));
    add_size_options(*sub, opt->size);
    sub->add_option("--smooth", opt->smooth, "Laplacian smoothing iterations of the interior vertices (default 5)")
        ->check(CLI::Range(0, 1000));
    sub->add_option("--feature-angle", opt->feature_angle,
                    "Sharp features: input edges whose normals deviate by more than DEG degrees are kept as hex "
                    "creases (default 45; 0: off)")
        ->check(CLI::Range(0.0, 179.0));
    sub->add_option("--min-quality", opt->min_quality,
                    "Target minimum scaled Jacobian of the optimiser (default 0.5): optimise until reached or no progress")
        ->check(CLI::Range(0.0, 1.0));
    sub->add_option("--core-fill-margin", opt->core_fill_margin,
                    "Fill hexes (grown through to close tunnels and join thin parts of the core): corners at least "
                    "this x their edge inside the surface (default 0.02; negative: no fill)");
    sub->add_option("--core-margin", opt->core_margin,
                    "Core hexes have all corners at least this times their mean edge inside the surface (default 0.1)")
        ->check(CLI::Range(0.0, 2.0));
    sub->add_option("--optimise-work", opt->optimise_work,
                    "Optimiser work budget: vertex visits per mesh vertex (default 100; 0: only the sweep bounds). "
                    "Counted, not timed: the same input gives the same mesh on any machine")
        ->check(CLI::Range(0.0, 1e6));
    sub->add_option("--optimise-ms", opt->optimise_ms,
                    "Opt-in wall-clock safety bound of the optimiser in ms (default 0: none). When it stops the "
                    "optimiser the mesh depends on the machine's speed and load (optimise.hit_time_limit)")
        ->check(CLI::Range(0.0, 1e7));
    sub->add_option("--feature-min-chain", opt->feature_min_chain,
                    "Chains of sharp input edges shorter than this fraction of the bbox diagonal are not features "
                    "(default 0.1; 0: every sharp edge; keeps tessellation creases of organic models off)")
        ->check(CLI::Range(0.0, 10.0));
    sub->add_option("--pad-ray-limit", opt->pad_ray_limit,
                    "Pad: an outer vertex is the normal ray's hit if it is within this times (distance + edge), else "
                    "the closest point (default 2; 0: always the closest point)")
        ->check(CLI::Range(0.0, 100.0));
    sub->add_flag("--feature-path-rule", opt->path_rule,
                  "Features: a path takes no two edges of one boundary quad where the curve runs straight, unless "
                  "no other path is found (opt-in)");
    sub->add_flag("--no-release", opt->no_release,
                  "Optimise: do not free the hexes left flat or inverted by releasing their feature roles");
    sub->add_flag("--accept-topology-change", opt->accept_topology_change,
                  "Exit 0 even if the boundary's components or Euler characteristics differ from the input's");
    add_threads_option(*sub, opt->threads);
    add_json_flag(*sub, opt->json);
    add_no_progress_flag(*sub, opt->no_progress);
    sub->callback([opt] { run_mesh(*opt); });
}

}  // namespace dualhex::app
