// mesh_stage_distance: the two-sided surface distance (geometry/surface_distance.hpp, % of
// the bbox diagonal) of the mesh after each moving stage (pad, features, smooth, optimise),
// to tell which stage leaves the hex boundary far from the input. Not a test.
//   mesh_stage_distance MODEL [--refine-rounds N] [--refine-distance D]
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_distance.hpp"
#include "dualhex/mesher/mesh_pipeline.hpp"

using namespace dualhex;

namespace {

// How far the stage moved the boundary (non-Interior) vertices, in target sizes: the
// largest move and where it ended, and how many moved more than one target size (a
// vertex carried over a thin part or onto another sheet shows here).
void print_boundary_moves(std::string_view stage, const mesher::MeshPipelineResult& r,
                          std::vector<Eigen::Vector3d>& before) {
    if (before.size() == r.mesh.points.size()) {
        double largest = 0;
        std::size_t far = 0, at = 0;
        for (std::size_t v = 0; v < before.size(); ++v) {
            if (r.constraints.role[v] == mesher::VertexRole::Interior) continue;
            const double moved = (r.mesh.points[v] - before[v]).norm() / r.target_size;
            far += moved > 1 ? 1 : 0;
            if (moved > largest) largest = moved, at = v;
        }
        const Eigen::Vector3d& p = r.mesh.points[at];
        std::printf("          %s moved boundary vertices: max %.2f target sizes (to %.4g %.4g %.4g), %zu > 1\n",
                    std::string(stage).c_str(), largest, p.x(), p.y(), p.z(), far);
    }
    before = r.mesh.points;
}

}  // namespace

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
    std::vector<Eigen::Vector3d> before;  // the points as the previous stage left them
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
        print_boundary_moves(stage, r, before);
    };
    const mesher::MeshPipelineResult r = mesher::mesh_surface(tree, options);
    for (std::size_t n = 0; n < r.refine.places.size(); ++n)
        std::printf("refine round %zu: %zu unresolved places\n", n, r.refine.places[n]);
    std::printf("refine: rounds %d, leaves split %zu\n", r.refine.rounds, r.refine.split);
    return 0;
}
