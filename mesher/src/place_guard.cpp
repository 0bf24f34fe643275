// The optimiser's contract place by place (place_guard.hpp).
#include "place_guard.hpp"

#include <algorithm>
#include <cmath>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/union_find.hpp"

namespace dualhex::mesher::detail {
namespace {

struct PlaceQuality {
    std::size_t inverted = 0, flat = 0;
    double min = 1;
    void add(double sj, double flat_below) {
        inverted += !(sj > 0);
        flat += !(sj > flat_below);
        min = std::min(min, std::isnan(sj) ? -1.0 : sj);
    }
};

bool worse(const PlaceQuality& after, const PlaceQuality& before) {
    return after.inverted > before.inverted || after.flat > before.flat || after.min < before.min;
}

}  // namespace

PlaceGuardResult restore_worse_places(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before,
                                      const std::vector<double>& sj_before, double flat) {
    const std::size_t n = mesh.points.size();
    std::vector<char> moved(n, 0);
    for (std::size_t v = 0; v < n; ++v) moved[v] = mesh.points[v] != before[v];
    geometry::UnionFind places(n);  // a place is named by its smallest vertex
    std::vector<std::size_t> touched;  // hexes with a moved corner, in hex order
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        std::size_t first = n;
        for (int v : mesh.hexes[h]) {
            const auto u = static_cast<std::size_t>(v);
            if (!moved[u]) continue;
            if (first == n) first = u;
            places.unite(first, u);
        }
        if (first != n) touched.push_back(h);
    }
    std::vector<PlaceQuality> was(n), is(n);  // indexed by the place's root
    for (std::size_t h : touched) {
        std::size_t root = n;
        for (int v : mesh.hexes[h])
            if (moved[static_cast<std::size_t>(v)]) root = places.find(static_cast<std::size_t>(v));
        was[root].add(sj_before[h], flat);
        is[root].add(geometry::scaled_jacobian(mesh, h), flat);
    }
    PlaceGuardResult result;
    std::vector<char> put_back(n, 0);
    for (std::size_t v = 0; v < n; ++v) {
        if (!moved[v] || places.find(v) != v) continue;
        ++result.places;
        if (worse(is[v], was[v])) {
            put_back[v] = 1;
            ++result.restored;
        }
    }
    for (std::size_t v = 0; v < n; ++v)
        if (moved[v] && put_back[places.find(v)]) mesh.points[v] = before[v];
    return result;
}

}  // namespace dualhex::mesher::detail
