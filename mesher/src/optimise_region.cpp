// The optimiser on a region of the mesh (optimise.hpp optimise_region): the region cut out
// as a mesh of its own whose border vertices are held, optimised, written back.
#include <algorithm>
#include <array>

#include "dualhex/mesher/optimise.hpp"

namespace dualhex::mesher {
namespace {

std::vector<std::vector<int>> hexes_at(const geometry::HexMesh& mesh) {
    std::vector<std::vector<int>> at(mesh.points.size());
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (int v : mesh.hexes[h]) at[static_cast<std::size_t>(v)].push_back(static_cast<int>(h));
    return at;
}

}  // namespace

OptimiseResult optimise_region(geometry::HexMesh& mesh, const std::vector<std::size_t>& seeds, int rings,
                               const VertexConstraints& constraints, const geometry::AabbTree& tree,
                               const FeatureCurves& curves, const OptimiseOptions& options) {
    const std::vector<std::vector<int>> at = hexes_at(mesh);
    std::vector<char> in_region(mesh.hexes.size(), 0);
    std::vector<std::size_t> region;
    for (std::size_t h : seeds)
        if (!in_region[h]) {
            in_region[h] = 1;
            region.push_back(h);
        }
    for (int r = 0; r < rings; ++r)
        for (std::size_t i = 0, n = region.size(); i < n; ++i)
            for (int v : mesh.hexes[region[i]])
                for (int g : at[static_cast<std::size_t>(v)])
                    if (!in_region[static_cast<std::size_t>(g)]) {
                        in_region[static_cast<std::size_t>(g)] = 1;
                        region.push_back(static_cast<std::size_t>(g));
                    }
    std::sort(region.begin(), region.end());  // the same sub-mesh whatever the seeds' order
    geometry::HexMesh sub;
    std::vector<int> local(mesh.points.size(), -1);
    std::vector<std::size_t> global;
    for (std::size_t h : region) {
        std::array<int, 8> ids{};
        for (std::size_t k = 0; k < 8; ++k) {
            const auto v = static_cast<std::size_t>(mesh.hexes[h][k]);
            if (local[v] < 0) {
                local[v] = static_cast<int>(global.size());
                global.push_back(v);
                sub.points.push_back(mesh.points[v]);
            }
            ids[k] = local[v];
        }
        sub.hexes.push_back(ids);
    }
    VertexConstraints c = VertexConstraints::interior(global.size());
    for (std::size_t i = 0; i < global.size(); ++i) {
        bool inside = true;  // all its hexes in the region: it may move
        for (int g : at[global[i]]) inside = inside && in_region[static_cast<std::size_t>(g)];
        c.role[i] = inside ? constraints.role[global[i]] : VertexRole::Corner;
        c.curve[i] = inside ? constraints.curve[global[i]] : -1;
    }
    QualityState state = quality_state(sub);
    const OptimiseResult r = optimise_mesh(sub, c, tree, curves, options, state);
    for (std::size_t i = 0; i < global.size(); ++i) mesh.points[global[i]] = sub.points[i];
    return r;
}

}  // namespace dualhex::mesher
