// geometry_bench: times the geometric layer's foundations on shared surface models.
//
//   geometry_bench [model.off|model.stl ...]   (default: 3 shared models)
//
// Per model: load (read_surface), AABB tree build, then for max depth 6 and 7 the
// surface octree (local thickness + refinement, default options), pair(Strong) and
// pair(Weak) on it, with leaf counts. Two stopping rules: "lfs" = the default (cell edge
// <= 0.5 * local thickness, or max depth), "all" = thickness_factor 0 (every crossing
// cell down to max depth). Prints the machine (uname -n, CPU model) first.
#include "machine.hpp"
#include <sys/utsname.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/surface.hpp"
#include "dualhex/geometry/surface_octree.hpp"
#include "dualhex/grid/refinement.hpp"

using namespace dualhex;
using namespace dualhex::geometry;

namespace {

template <class F>
double seconds(F&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> models;
    for (int a = 1; a < argc; ++a) models.emplace_back(argv[a]);
    if (models.empty())
        for (const char* m : {"cgal_elephant.off", "gao_bunny_tri.off", "cgal_armadillo.off"})
            models.push_back(std::string(DUALHEX_SHARED_DATA) + "/surfaces/" + m);

    utsname u{};
    uname(&u);
    std::printf("machine: %s, CPU: %s\n\n", u.nodename, dualhex::bench::cpu_model().c_str());
    std::printf("%-20s %7s %7s %7s %4s %2s %8s %9s %8s %9s %8s %9s %6s\n", "model", "tris", "load_s", "tree_s", "stop", "d",
                "octree_s", "leaves", "strong_s", "strong", "weak_s", "weak", "s/w");
    try {
        for (const auto& path : models) {
            TriangleSurface s;
            const double t_load = seconds([&] { s = read_surface(path); });
            const std::size_t tris = s.triangles.size();
            std::optional<AabbTree> tree;
            const double t_tree = seconds([&] { tree.emplace(std::move(s)); });
            const std::string name = path.substr(path.find_last_of('/') + 1);
            for (const double factor : {0.5, 0.0})
            for (int depth : {6, 7}) {
                SurfaceOctreeOptions opt;
                opt.max_depth = depth;
                opt.thickness_factor = factor;
                std::optional<SurfaceOctree> oct;
                const double t_oct = seconds([&] { oct.emplace(surface_octree(*tree, opt)); });
                std::optional<LeafGrid> strong, weak;
                const double t_strong = seconds([&] { strong.emplace(pair(oct->grid, Balance::Strong)); });
                const double t_weak = seconds([&] { weak.emplace(pair(oct->grid, Balance::Weak)); });
                std::printf("%-20s %7zu %7.3f %7.3f %4s %2d %8.3f %9zu %8.3f %9zu %8.3f %9zu %6.3f\n", name.c_str(), tris,
                            t_load, t_tree, factor > 0 ? "lfs" : "all", depth, t_oct, oct->grid.size(), t_strong, strong->size(), t_weak,
                            weak->size(), double(strong->size()) / double(weak->size()));
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "geometry_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
