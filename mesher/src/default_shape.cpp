// The embedded default shape (default_shape.hpp).
#include "dualhex/mesher/default_shape.hpp"

#include <cmath>
#include <numbers>

namespace dualhex::mesher {

geometry::TriangleSurface default_shape() {
    constexpr int nu = 48, nv = 24;
    constexpr double R = 1.0, r = 0.4;
    geometry::TriangleSurface s;
    s.source = "<default torus>";
    for (int i = 0; i < nu; ++i) {
        const double u = 2 * std::numbers::pi * i / nu;
        for (int j = 0; j < nv; ++j) {
            const double v = 2 * std::numbers::pi * j / nv;
            s.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                    r * std::sin(v));
        }
    }
    auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            s.triangles.push_back({a, b, c});
            s.triangles.push_back({a, c, d});
        }
    // clean_surface checks closedness and flips the orientation outward if needed.
    return geometry::clean_surface(std::move(s));
}

}  // namespace dualhex::mesher
