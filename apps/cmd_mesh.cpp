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

#include "commands.hpp"
#include "histogram_format.hpp"

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/geometry/surface.hpp"

namespace dualhex::app {
namespace {

struct MeshOptionsCli {
    std::string input, output, balance = "weak";
    int max_depth = 6, smooth = 5;
    bool json = false, force = false;
};

void run_mesh(const MeshOptionsCli& opt) {
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
    options.balance = opt.balance == "strong" ? Balance::Strong : Balance::Weak;
    options.max_depth = opt.max_depth;
    options.smooth_iterations = opt.smooth;
    if (progress) options.progress = [](const std::string& s) { std::cerr << "  " << s << "...\n"; };
    mesher::MeshPipelineResult r = mesher::mesh_surface(tree, options);

    if (progress) std::cerr << "  write...\n";
    const auto t0 = std::chrono::steady_clock::now();
    geometry::write_hex_mesh(opt.output, r.mesh, opt.force);
    r.ms.write = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    const auto& q = r.quality;
    if (opt.json) {
        print_json({{"input", input_name},
                    {"output", opt.output},
                    {"balance", opt.balance},
                    {"max_depth", opt.max_depth},
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
        std::printf("%s: %zu triangles, max depth %d, %s balance\n", input_name.c_str(), triangles, opt.max_depth,
                    opt.balance.c_str());
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
    sub->add_option("--max-depth", opt->max_depth, "Octree max depth (default 6)")->check(CLI::Range(1, 10));
    sub->add_option("--smooth", opt->smooth, "Laplacian smoothing iterations of the interior vertices (default 5)")
        ->check(CLI::Range(0, 1000));
    add_json_flag(*sub, opt->json);
    sub->callback([opt] { run_mesh(*opt); });
}

}  // namespace dualhex::app
