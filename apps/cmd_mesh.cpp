// dualhex mesh [INPUT] -o OUT: a closed triangle surface (OBJ/OFF/STL/PLY; none: the
// embedded default torus) to an all-hex mesh, through the octree, pairing + balancing,
// element installation, the clipped dual, extraction of the hexes inside, projection of
// the boundary onto the surface and Laplacian smoothing (mesher/mesh_pipeline.hpp).
// Writes OUT by extension (.vtk, .vtu, .mesh) and reports quality and times.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "histogram_format.hpp"

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::app {
namespace {

struct MeshOptionsCli {
    std::string input, output, balance = "weak", preset = "medium";
    int smooth = 5;
    bool json = false, force = false;
    // Size control (mesher/mesh_size.hpp): the preset's values unless given.
    std::optional<double> size, size_rel, surface_band, thickness_factor, curvature_angle;
    std::optional<int> min_depth, max_depth, curvature_levels, thickness_levels;
    std::optional<std::size_t> max_leaves;
};

// The preset, overridden by the size options given; refused (exit 2) if inconsistent.
mesher::MeshSizeOptions size_options(const MeshOptionsCli& opt) {
    mesher::MeshSizeOptions s = mesher::mesh_preset(*mesher::parse_mesh_preset(opt.preset));
    if (opt.size) {
        s.size = *opt.size;
        s.size_rel = 0;
        if (!(*opt.size > 0)) throw UsageError("--size must be > 0, got " + std::to_string(*opt.size));
    }
    if (opt.size_rel) {
        s.size_rel = *opt.size_rel;
        if (!(*opt.size_rel > 0)) throw UsageError("--size-rel must be > 0, got " + std::to_string(*opt.size_rel));
    }
    if (opt.surface_band) s.surface_band = *opt.surface_band;
    if (opt.thickness_factor) s.thickness_factor = *opt.thickness_factor;
    if (opt.curvature_angle) s.curvature_angle = *opt.curvature_angle;
    if (opt.min_depth) s.min_depth = *opt.min_depth;
    if (opt.max_depth) s.max_depth = *opt.max_depth;
    if (opt.curvature_levels) s.curvature_levels = *opt.curvature_levels;
    if (opt.thickness_levels) s.thickness_levels = *opt.thickness_levels;
    if (opt.max_leaves) s.max_leaves = *opt.max_leaves;
    try {
        mesher::check_size_options(s);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    return s;
}

// Warns when the size asks for cells finer than the depth cap allows.
void warn_if_capped(const mesher::MeshSizeOptions& s, const geometry::AabbTree& tree) {
    const geometry::RootCube root = geometry::root_cube(tree.bounds(), geometry::SurfaceOctreeOptions{}.margin);
    const double size = mesher::target_size(s, tree.bounds());
    const int level = geometry::level_for_size(root, size);
    if (level > s.max_depth)
        std::cerr << "warning: size " << size << " needs depth " << level << ", capped at --max-depth "
                  << s.max_depth << ": cells at the surface will be " << root.edge(s.max_depth) << '\n';
}

void run_mesh(const MeshOptionsCli& opt) {
    const mesher::MeshSizeOptions size = size_options(opt);
    {  // before any work: the format and the overwrite check
        const std::string ext = std::filesystem::path(opt.output).extension().string();
        if (ext != ".vtk" && ext != ".vtu" && ext != ".mesh")
            throw UsageError("output '" + opt.output + "': unknown format (use .vtk, .vtu or .mesh)");
        check_output(opt.output, opt.force);
    }
    const bool progress = !opt.json && isatty(STDERR_FILENO);
    const std::string input_name = opt.input.empty() ? "<default torus>" : opt.input;

    geometry::TriangleSurface surface;
    geometry::SurfaceReport report;
    try {
        surface = opt.input.empty() ? mesher::default_shape() : geometry::read_surface(opt.input, {}, &report);
    } catch (const geometry::SurfaceError& e) {  // what() names the file
        std::cerr << "error: " << e.what() << '\n';
        throw Exit{kInputError};
    }
    if (progress)
        for (const auto& w : report.warnings) std::cerr << "warning: " << input_name << ": " << w << '\n';
    const std::size_t triangles = surface.triangles.size();
    const geometry::AabbTree tree(std::move(surface));

    mesher::MeshPipelineOptions options;
    static_cast<mesher::MeshSizeOptions&>(options) = size;
    options.balance = opt.balance == "strong" ? Balance::Strong : Balance::Weak;
    options.smooth_iterations = opt.smooth;
    if (progress) options.progress = [](const std::string& s) { std::cerr << "  " << s << "...\n"; };
    warn_if_capped(size, tree);
    mesher::MeshPipelineResult r;
    try {
        r = mesher::mesh_surface(tree, options);
    } catch (const geometry::OctreeTooLarge& e) {
        throw UsageError(std::string(e.what()) + " (a coarser --size or --size-rel, or raise --max-leaves)");
    }

    if (progress) std::cerr << "  write...\n";
    const auto t0 = std::chrono::steady_clock::now();
    geometry::write_hex_mesh(opt.output, r.mesh, opt.force, r.cell_data);
    r.ms.write = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    const auto& q = r.quality;
    if (opt.json) {
        print_json({{"input", input_name},
                    {"output", opt.output},
                    {"balance", opt.balance},
                    {"max_depth", size.max_depth},
                    {"size",
                     {{"preset", opt.preset},
                      {"target", r.target_size},
                      {"size_level", r.size_level},
                      {"octree_depth", r.octree_depth},
                      {"min_depth", size.min_depth},
                      {"thickness_factor", size.thickness_factor},
                      {"curvature_angle", size.curvature_angle},
                      {"curvature_levels", size.curvature_levels},
                      {"curvature_splits", r.curvature_splits},
                      {"thickness_levels", size.thickness_levels},
                      {"surface_band", size.surface_band}}},
                    {"triangles", triangles},
                    {"leaves", r.leaves},
                    {"cells", r.cells},
                    {"dual_hexes", r.dual_hexes},
                    {"hexes", r.mesh.hexes.size()},
                    {"vertices", r.mesh.points.size()},
                    {"boundary_vertices", r.boundary_vertices},
                    {"inverted_after_projection", r.inverted_after_projection},
                    {"smooth_iterations", r.smooth_iterations_done},
                    {"untangled_vertices", r.untangled_vertices},
                    {"scaled_jacobian",
                     {{"min", q.min}, {"mean", q.mean}, {"below_0", q.share_negative}, {"below_0_2", q.share_below_02}}},
                    {"singular_edge_valences", histogram_json(r.singular_edge_valences)},
                    {"hausdorff", r.hausdorff.max},
                    {"hausdorff_mean", r.hausdorff.mean},
                    {"ms",
                     {{"octree", r.ms.octree},
                      {"balance", r.ms.balance},
                      {"pair", r.ms.pair},
                      {"balance_pair", r.ms.balance_pair},
                      {"install", r.ms.install},
                      {"verify", r.ms.verify},
                      {"dual", r.ms.dual},
                      {"extract", r.ms.extract},
                      {"project", r.ms.project},
                      {"smooth", r.ms.smooth},
                      {"untangle", r.ms.untangle},
                      {"report", r.ms.report},
                      {"write", r.ms.write}}}});
    } else {
        std::printf("%s: %zu triangles, %s balance\n", input_name.c_str(), triangles, opt.balance.c_str());
        std::printf("size:             %.4g at the surface (%s preset; level %d), octree depth %d (max %d)\n",
                    r.target_size, opt.preset.c_str(), r.size_level, r.octree_depth, size.max_depth);
        std::printf("grid:             %zu leaves, %zu installed cells, %zu dual hexes\n", r.leaves, r.cells,
                    r.dual_hexes);
        std::printf("mesh:             %zu hexes, %zu vertices (%zu on the boundary, projected)\n",
                    r.mesh.hexes.size(), r.mesh.points.size(), r.boundary_vertices);
        std::printf("scaled Jacobian:  min %.4f, mean %.4f, < 0: %.4f%%, < 0.2: %.4f%%\n", q.min, q.mean,
                    100 * q.share_negative, 100 * q.share_below_02);
        std::printf("inverted:         %zu after projection; %d smoothing iterations; %zu vertex pull-backs\n",
                    r.inverted_after_projection, r.smooth_iterations_done, r.untangled_vertices);
        std::printf("singular edges:   %s (interior, valence: count)\n", histogram_text(r.singular_edge_valences).c_str());
        std::printf("surface distance: max %.3g, mean %.3g (of the bbox diagonal)\n", r.hausdorff.max,
                    r.hausdorff.mean);
        std::printf("time (ms):        octree %.1f, balance+pair %.1f, install %.1f, verify %.1f, dual %.1f, "
                    "extract %.1f, project %.1f, smooth %.1f, untangle %.1f, report %.1f, write %.1f\n",
                    r.ms.octree, r.ms.balance_pair, r.ms.install, r.ms.verify, r.ms.dual, r.ms.extract, r.ms.project,
                    r.ms.smooth, r.ms.untangle, r.ms.report, r.ms.write);
        std::printf("wrote %s\n", opt.output.c_str());
    }
}

void add_size_options(CLI::App& sub, MeshOptionsCli& opt) {
    const std::string g = "Size";
    sub.add_option("--preset", opt.preset, "coarse, medium (default) or fine: about 5k, 20k, 100k hexes on the bunny")
        ->check(CLI::IsMember({"coarse", "medium", "fine"}))->group(g);
    auto* size = sub.add_option("--size", opt.size, "Target cell size at the surface, model units")->group(g);
    sub.add_option("--size-rel", opt.size_rel, "Target size as a fraction of the bbox diagonal (medium: 0.02)")
        ->excludes(size)->group(g);
    sub.add_option("--surface-band", opt.surface_band,
                   "Cells within this many target sizes of the surface get the target size too (default 0)")->group(g);
    sub.add_option("--min-depth", opt.min_depth, "Octree min depth (default 0)")->group(g);
    sub.add_option("--max-depth", opt.max_depth,
                   "Octree depth cap, 1.." + std::to_string(mesher::kMaxMeshDepth) + " (default 12)")->group(g);
    sub.add_option("--thickness-factor", opt.thickness_factor,
                   "Cells at the surface at most this * the local thickness; 0: off (default 0.5)")->group(g);
    sub.add_option("--thickness-levels", opt.thickness_levels,
                   "Thickness refines at most this many levels below the target size (default 3)")->group(g);
    sub.add_option("--curvature-angle", opt.curvature_angle,
                   "Refine cells where the surface normal turns more than this (degrees; 0: off; default 40)")
        ->group(g);
    sub.add_option("--curvature-levels", opt.curvature_levels,
                   "Curvature refines at most this many levels below the target size (default 1)")->group(g);
    sub.add_option("--max-leaves", opt.max_leaves, "Refuse octrees beyond this many leaves (default 2000000)")
        ->group(g);
}

}  // namespace

void register_mesh(CLI::App& app) {
    auto opt = std::make_shared<MeshOptionsCli>();
    CLI::App* sub = app.add_subcommand(
        "mesh", "Mesh a closed triangle surface (OBJ/OFF/STL/PLY; default: a torus) with hexahedra: octree, "
                "balance + pair, install, clipped dual, keep the hexes inside, project, smooth; write OUT "
                "(.vtk, .vtu or .mesh)");
    sub->add_option("input", opt->input, "Surface file (closed, manifold); omitted: the embedded torus");
    sub->add_option("-o,--output", opt->output, "Output hex mesh (.vtk, .vtu or .mesh)")->required();
    sub->add_flag("--force", opt->force, "Overwrite the output file if it exists");
    sub->add_option("--balance", opt->balance, "weak (default, weak rule) or strong (strong rule)")
        ->check(CLI::IsMember({"weak", "strong"}));
    add_size_options(*sub, *opt);
    sub->add_option("--smooth", opt->smooth, "Laplacian smoothing iterations of the interior vertices (default 5)")
        ->check(CLI::Range(0, 1000));
    add_json_flag(*sub, opt->json);
    sub->callback([opt] { run_mesh(*opt); });
}

}  // namespace dualhex::app
