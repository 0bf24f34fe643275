#pragma once
// mesh_quality: two-sided distance between triangle sets, with its own acceleration (a
// uniform grid of triangle bounding boxes, searched in growing shells of cells) and its
// own point-triangle distance (inside the prism: the plane distance; else the nearest of
// the three edge segments). Independent of the geometry layer's AabbTree.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "mesh_quality_vtk.hpp"

namespace mesh_quality {

inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

using Triangle = std::array<Vec3, 3>;

inline double segment_distance2(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = dot(ab, ab);
    const double t = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const Vec3 d = p - (a + t * ab);
    return dot(d, d);
}

inline double triangle_distance2(const Vec3& p, const Triangle& t) {
    const Vec3 n = cross(t[1] - t[0], t[2] - t[0]);
    const double n2 = dot(n, n);
    if (n2 > 0) {
        bool inside = true;  // p's projection on the same side of all three edges as the triangle
        for (int i = 0; i < 3; ++i) inside = inside && dot(cross(t[(i + 1) % 3] - t[i], p - t[i]), n) >= 0;
        if (inside) {
            const double h = dot(p - t[0], n);
            return h * h / n2;
        }
    }
    return std::min(
        {segment_distance2(p, t[0], t[1]), segment_distance2(p, t[1], t[2]), segment_distance2(p, t[2], t[0])});
}

class TriangleGrid {
public:
    explicit TriangleGrid(std::vector<Triangle> triangles) : tris_(std::move(triangles)) {
        lo_ = hi_ = tris_.at(0)[0];
        for (const auto& t : tris_)
            for (const auto& p : t) {
                lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
                hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y), std::max(hi_.z, p.z)};
            }
        const Vec3 size = hi_ - lo_;
        const double volume = std::max(size.x, 1e-12) * std::max(size.y, 1e-12) * std::max(size.z, 1e-12);
        cell_ = std::cbrt(volume / static_cast<double>(tris_.size()));  // about one triangle per cell
        cell_ = std::max({cell_, size.x / 256, size.y / 256, size.z / 256, 1e-12});
        for (int a = 0; a < 3; ++a) n_[a] = std::max(1, static_cast<int>(std::ceil(axis(size, a) / cell_)));
        start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
        for (int pass = 0; pass < 2; ++pass) {  // count, then fill (CSR)
            std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
            if (pass == 1) items_.resize(start_.back());
            for (std::size_t t = 0; t < tris_.size(); ++t) {
                std::array<int, 3> from{}, to{};
                for (int a = 0; a < 3; ++a) {
                    double mn = axis(tris_[t][0], a), mx = mn;
                    for (const auto& p : tris_[t]) mn = std::min(mn, axis(p, a)), mx = std::max(mx, axis(p, a));
                    from[a] = index(mn, a);
                    to[a] = index(mx, a);
                }
                for (int k = from[2]; k <= to[2]; ++k)
                    for (int j = from[1]; j <= to[1]; ++j)
                        for (int i = from[0]; i <= to[0]; ++i) {
                            const std::size_t c = cell_id(i, j, k);
                            if (pass == 0)
                                ++start_[c + 1];
                            else
                                items_[fill[c]++] = static_cast<std::uint32_t>(t);
                        }
            }
            if (pass == 0)
                for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        }
    }

    // Distance from p to the nearest triangle: shells of cells around p's (clamped) cell,
    // until the nearest distance found is below the shell's distance from p.
    [[nodiscard]] double distance(const Vec3& p) const {
        std::array<int, 3> c{};
        double outside2 = 0;  // squared distance from p to the grid box
        for (int a = 0; a < 3; ++a) {
            c[a] = index(axis(p, a), a);
            const double d = std::max({axis(lo_, a) - axis(p, a), 0.0, axis(p, a) - axis(hi_, a)});
            outside2 += d * d;
        }
        double best2 = std::numeric_limits<double>::infinity();
        const int max_ring = std::max({n_[0], n_[1], n_[2]});
        for (int r = 0; r <= max_ring; ++r) {
            for (int k = c[2] - r; k <= c[2] + r; ++k)
                for (int j = c[1] - r; j <= c[1] + r; ++j) {
                    // on the shell: all i if j or k is at distance r, else only the two ends
                    const int step = (std::abs(j - c[1]) == r || std::abs(k - c[2]) == r) ? 1 : std::max(1, 2 * r);
                    for (int i = c[0] - r; i <= c[0] + r; i += step) {
                        if (i < 0 || j < 0 || k < 0 || i >= n_[0] || j >= n_[1] || k >= n_[2]) continue;
                        const std::size_t id = cell_id(i, j, k);
                        for (std::size_t s = start_[id]; s < start_[id + 1]; ++s)
                            best2 = std::min(best2, triangle_distance2(p, tris_[items_[s]]));
                    }
                }
            // A point of an unsearched cell is >= r cells from p's (clamped) cell along some
            // axis, and inside the box: its squared distance is >= outside2 + (r cell)^2.
            if (best2 <= outside2 + (r * cell_) * (r * cell_)) break;
        }
        return std::sqrt(best2);
    }

private:
    static double axis(const Vec3& p, int a) { return a == 0 ? p.x : a == 1 ? p.y : p.z; }
    [[nodiscard]] int index(double x, int a) const {
        return std::clamp(static_cast<int>(std::floor((x - axis(lo_, a)) / cell_)), 0, n_[a] - 1);
    }
    [[nodiscard]] std::size_t cell_id(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(n_[0]) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(n_[1]) * static_cast<std::size_t>(k));
    }
    std::vector<Triangle> tris_;
    Vec3 lo_, hi_;
    double cell_ = 1;
    std::array<int, 3> n_{1, 1, 1};
    std::vector<std::size_t> start_;
    std::vector<std::uint32_t> items_;
};

// Points on a triangle: the barycentric grid with `n` steps per edge (corners included).
template <class Visit>
void sample_triangle(const Triangle& t, double spacing, Visit&& visit) {
    const double longest = std::sqrt(
        std::max({dot(t[1] - t[0], t[1] - t[0]), dot(t[2] - t[1], t[2] - t[1]), dot(t[0] - t[2], t[0] - t[2])}));
    const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, 32);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j)
            visit(t[0] + (static_cast<double>(i) / n) * (t[1] - t[0]) + (static_cast<double>(j) / n) * (t[2] - t[0]));
}

struct OneWay {
    double mean = 0, max = 0;
};

// Samples of `from` (spacing apart) against `to`.
inline OneWay one_way(const std::vector<Triangle>& from, const TriangleGrid& to, double spacing) {
    OneWay w;
    double sum = 0;
    std::size_t count = 0;
    for (const auto& t : from)
        sample_triangle(t, spacing, [&](const Vec3& p) {
            const double d = to.distance(p);
            sum += d;
            ++count;
            w.max = std::max(w.max, d);
        });
    w.mean = count ? sum / static_cast<double>(count) : 0;
    return w;
}

}  // namespace mesh_quality
