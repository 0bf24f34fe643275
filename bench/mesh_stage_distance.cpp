// mesh_stage_distance: the two-sided surface distance (geometry/surface_distance.hpp, % of
// the bbox diagonal) of the mesh after each moving stage (pad, features, smooth, optimise),
// to tell which stage leaves the hex boundary far from the input. Not a test.
//   mesh_stage_distance MODEL [--refine-rounds N] [--refine-distance D]
#include <cstdio>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_distance.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"

using namespace dualhex;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: mesh_stage_distance MODEL [--refine-rounds N] [--refine-distance D]\n");
        return 2;
    }
    mesher::MeshPipelineOptions options;
    for (int a = 2; a + 1 < argc; a += 2)
        if (std::string(argv[a]) == "--refine-rounds") options.refine_rounds = std::stoi(argv[a + 1]);
        else if (std::string(argv[a]) == "--refine-distance") options.refine_distance = std::stod(argv[a + 1]);
    const geometry::AabbTree tree(geometry::read_surface(argv[1]));
    options.observe = [&](std::string_view stage, const mesher::MeshPipelineResult& r, const mesher::QualityState&) {
        const geometry::SurfaceDistance d = geometry::surface_distance(r.mesh, tree);
        std::printf("%-9s hexes %7zu  mesh->surface max %.3f%%  surface->mesh max %.3f%%  mean %.4f%%\n",
                    std::string(stage).c_str(), r.mesh.hexes.size(), 100 * d.relative(d.mesh_to_surface.max),
                    100 * d.relative(d.surface_to_mesh.max), 100 * d.relative(d.mean()));
        // Which side is far tells the cause: a hex-boundary point far from the input is a pad
        // quad bridging empty space; an input point far from the mesh a part the core misses.
        const Eigen::Vector3d& f = d.mesh_to_surface.farthest;
        const Eigen::Vector3d& g = d.surface_to_mesh.farthest;
        std::printf("          farthest hex-boundary point (%.4g %.4g %.4g), farthest input point (%.4g %.4g %.4g)\n",
                    f.x(), f.y(), f.z(), g.x(), g.y(), g.z());
    };
    const mesher::MeshPipelineResult r = mesher::mesh_surface(tree, options);
    for (std::size_t n = 0; n < r.refine.places.size(); ++n)
        std::printf("refine round %zu: %zu unresolved places\n", n, r.refine.places[n]);
    std::printf("refine: rounds %d, leaves split %zu\n", r.refine.rounds, r.refine.split);
    return 0;
}
