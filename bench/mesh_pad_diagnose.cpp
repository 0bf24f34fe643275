// mesh_pad_diagnose: why hexes of a `dualhex mesh` run are bad, after each moving stage
// (pad, features, smooth, optimise): mesher/pad_diagnosis.hpp counts, of the hexes below
// the threshold, core and pad hexes and the causes the pad hexes show. Not a test.
//
//   mesh_pad_diagnose MODEL [--preset coarse|medium|fine] [--threshold 0.3]
//                     [--core-smoothing N] [--core-floor F] [--normal-smoothing N]  (pad.hpp options)
//                     [--rescue N]  (optimise.hpp rescue_rounds)
//                     [--cleanup | --no-cleanup] [--cleanup-margin F] [--cleanup-remove-depth F]  (core_cleanup.hpp, CoreOptions)
#include <algorithm>
#include <cstdio>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"
#include "dualhex/mesher/pad_diagnosis.hpp"

using namespace dualhex;
using namespace dualhex::mesher;

int main(int argc, char** argv) {
    std::string model, preset = "medium";
    double threshold = 0.3;
    MeshPipelineOptions options;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--preset" && a + 1 < argc) preset = argv[++a];
        else if (arg == "--threshold" && a + 1 < argc) threshold = std::stod(argv[++a]);
        else if (arg == "--core-smoothing" && a + 1 < argc) options.pad.core_smoothing = std::stoi(argv[++a]);
        else if (arg == "--core-floor" && a + 1 < argc) options.pad.core_smoothing_floor = std::stod(argv[++a]);
        else if (arg == "--normal-smoothing" && a + 1 < argc) options.pad.normal_smoothing = std::stoi(argv[++a]);
        else if (arg == "--no-cleanup") options.core.cleanup = false;
        else if (arg == "--cleanup") options.core.cleanup = true;
        else if (arg == "--cleanup-margin" && a + 1 < argc) options.core.cleanup_margin = std::stod(argv[++a]);
        else if (arg == "--cleanup-remove-depth" && a + 1 < argc) options.core.cleanup_remove_depth = std::stod(argv[++a]);
        else if (arg == "--rescue" && a + 1 < argc) options.optimise.rescue_rounds = std::stoi(argv[++a]);
        else model = arg;
    }
    const auto parsed = parse_mesh_preset(preset);
    if (model.empty() || !parsed) {
        std::fprintf(stderr, "usage: mesh_pad_diagnose MODEL [--preset coarse|medium|fine] [--threshold T]\n");
        return 2;
    }
    try {
        const geometry::AabbTree tree(geometry::read_surface(model));
        static_cast<MeshSizeOptions&>(options) = mesh_preset(*parsed);
        options.observe = [&](std::string_view stage, const MeshPipelineResult& r, const QualityState& s) {
            const PadDiagnosis d = diagnose_pad(r.mesh, r.core_hexes, r.constraints, s.scaled_jacobian, threshold);
            const double half = static_cast<double>(std::count_if(s.scaled_jacobian.begin(), s.scaled_jacobian.end(),
                                                                   [](double q) { return !(q >= 0.5); }));
            std::printf("%-9s min %.3f  < 0.5: %.2f %%  %s\n", std::string(stage).c_str(),
                        geometry::summarize(s.scaled_jacobian).min, 100.0 * half / static_cast<double>(s.scaled_jacobian.size()),
                        d.summary().c_str());
        };
        const MeshPipelineResult r = mesh_surface(tree, options);
        std::printf("hexes %zu (core %zu, pad %zu), optimise work %zu of %zu\n", r.mesh.hexes.size(), r.core_hexes,
                    r.pad_hexes, r.optimise.work, r.optimise.work_budget);
        std::printf("core cleanup: %zu removed, %zu added, %zu refused, %zu sweeps%s; topology %s\n", r.core.cleanup_removed,
                    r.core.cleanup_added, r.core.cleanup_refused, r.core.cleanup_sweeps,
                    r.core.cleanup_reverted ? " (reverted)" : "", r.topology.matches ? "matches the input" : "differs");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mesh_pad_diagnose: %s: %s\n", model.c_str(), e.what());
        return 1;
    }
    return 0;
}
