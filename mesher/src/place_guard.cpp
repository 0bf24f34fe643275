// The optimiser's contract place by place (place_guard.hpp).
#include "place_guard.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "dualhex/geometry/quality.hpp"

namespace dualhex::mesher::detail {
namespace {

struct Dsu {
    std::vector<std::size_t> up;
    explicit Dsu(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), std::size_t{0}); }
    std::size_t root(std::size_t x) {
        while (up[x] != x) x = up[x] = up[up[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) {
        a = root(a), b = root(b);
        if (a != b) up[std::max(a, b)] = std::min(a, b);  // the smallest vertex is the root
    }
};

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
bool better(const PlaceQuality& after, const PlaceQuality& before) {
    return after.inverted < before.inverted || after.flat < before.flat || after.min > before.min;
}

}  // namespace

PlaceGuardResult restore_worse_places(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& before,
                                      const std::vector<double>& sj_before, double flat, bool need_better) {
    const std::size_t n = mesh.points.size();
    std::vector<char> moved(n, 0);
    for (std::size_t v = 0; v < n; ++v) moved[v] = mesh.points[v] != before[v];
    Dsu places(n);
    std::vector<std::size_t> touched;  // hexes with a moved corner, in hex order
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h) {
        std::size_t first = n;
        for (int v : mesh.hexes[h]) {
            const auto u = static_cast<std::size_t>(v);
            if (!moved[u]) continue;
            if (first == n) first = u;
            places.join(first, u);
        }
        if (first != n) touched.push_back(h);
    }
    std::vector<PlaceQuality> was(n), is(n);  // indexed by the place's root
    for (std::size_t h : touched) {
        std::size_t root = n;
        for (int v : mesh.hexes[h])
            if (moved[static_cast<std::size_t>(v)]) root = places.root(static_cast<std::size_t>(v));
        was[root].add(sj_before[h], flat);
        is[root].add(geometry::scaled_jacobian(mesh, h), flat);
    }
    PlaceGuardResult result;
    std::vector<char> put_back(n, 0);
    for (std::size_t v = 0; v < n; ++v) {
        if (!moved[v] || places.root(v) != v) continue;
        ++result.places;
        const bool keep = !worse(is[v], was[v]) && (!need_better || better(is[v], was[v]));
        if (!keep) {
            put_back[v] = 1;
            ++result.restored;
        }
    }
    for (std::size_t v = 0; v < n; ++v)
        if (moved[v] && put_back[places.root(v)]) mesh.points[v] = before[v];
    return result;
}

}  // namespace dualhex::mesher::detail
