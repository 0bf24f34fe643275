// Phase 2 of the optimise stage (optimise.hpp): per-vertex moves that raise the local
// minimum scaled Jacobian, accepted only if they improve it.
#include <algorithm>
#include <array>
#include <cmath>

#include "optimise_detail.hpp"

namespace dualhex::mesher::detail {
namespace {

// Up the numerical gradient of the local minimum SJ at x (central differences).
Eigen::Vector3d min_sj_ascent(const VertexStarQuality& star, const Eigen::Vector3d& x, double h) {
    Eigen::Vector3d g;
    for (int a = 0; a < 3; ++a) {
        Eigen::Vector3d dx = Eigen::Vector3d::Zero();
        dx[a] = h;
        g[a] = star.at(x + dx).min - star.at(x - dx).min;
    }
    return g;
}

Eigen::Vector3d centroid_mean(const OptimiseContext& c, std::size_t v) {
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        for (int w : c.mesh.hexes[static_cast<std::size_t>(c.incidence.hex[i])]) m += c.mesh.points[static_cast<std::size_t>(w)];
    return m / (8.0 * static_cast<double>(c.incidence.count(v)));
}

// The best improving move of v among the candidates; true if v moved.
bool improve_vertex(OptimiseContext& c, const BarrierEnergy& e, std::size_t v) {
    const Eigen::Vector3d x = c.mesh.points[v];
    const VertexStarQuality star(c, v);
    const LocalQuality q0 = star.at(x);
    const double size = local_size(c, e, v);
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        (void)e.hex(c.mesh, static_cast<std::size_t>(c.incidence.hex[i]), static_cast<int>(v), x, &g);
    const Eigen::Vector3d to_centroids = centroid_mean(c, v) - x;
    const std::array<Eigen::Vector3d, 3> directions{
        c.domain.restrict(v, x, -g), c.domain.restrict(v, x, min_sj_ascent(star, x, 1e-4 * size)),
        c.domain.restrict(v, x, to_centroids)};
    const std::array<double, 3> first_step{0.3 * size, 0.3 * size, to_centroids.norm()};
    LocalQuality best = q0;
    Eigen::Vector3d best_x = x;
    for (std::size_t k = 0; k < directions.size(); ++k) {
        const double len = directions[k].norm();
        if (!(len > 0)) continue;
        double step = first_step[k];
        for (int halving = 0; halving < 8; ++halving, step *= 0.5) {
            const Eigen::Vector3d y = c.domain.project(v, x + (step / len) * directions[k], x);
            const LocalQuality q = star.at(y);
            if (q.better_than(best)) {
                best = q;
                best_x = y;
                break;  // the longest improving step of this direction
            }
        }
    }
    if (!best.better_than(q0)) return false;
    move_vertex(c, v, best_x);
    return true;
}

}  // namespace

std::size_t quality_phase(OptimiseContext& c, BarrierEnergy& energy, double target, int max_sweeps, int& sweeps) {
    std::size_t moves = 0;
    sweeps = 0;
    // A vertex that found no improving move is retried only after a vertex of one of its
    // hexes moved (its local quality cannot have changed otherwise).
    std::vector<char> dirty(c.mesh.points.size(), 1);
    constexpr int kStallSweeps = 10;  // sweeps without a better global minimum before stopping
    double best_min = -INFINITY;
    int best_sweep = 0;
    while (sweeps < max_sweeps && !c.stopped()) {
        // The movable vertices of the hexes below target, worst hex first.
        std::vector<std::pair<double, std::size_t>> order;
        std::vector<char> seen(c.mesh.points.size(), 0);
        std::vector<std::size_t> bad;
        for (std::size_t h = 0; h < c.sj.size(); ++h)
            if (!(c.sj[h] >= target)) bad.push_back(h);
        if (bad.empty()) break;
        std::sort(bad.begin(), bad.end(), [&](std::size_t a, std::size_t b) {
            return (std::isnan(c.sj[a]) ? -2.0 : c.sj[a]) < (std::isnan(c.sj[b]) ? -2.0 : c.sj[b]);
        });
        std::size_t moved = 0;
        for (std::size_t h : bad)
            for (int w : c.mesh.hexes[h]) {
                const auto v = static_cast<std::size_t>(w);
                if (seen[v] || !dirty[v] || c.domain.role(v) == VertexRole::Corner) continue;
                if (!c.take_visit()) break;
                seen[v] = 1;
                dirty[v] = 0;
                if (!improve_vertex(c, energy, v)) continue;
                ++moved;
                for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
                    for (int u : c.mesh.hexes[static_cast<std::size_t>(c.incidence.hex[i])]) dirty[static_cast<std::size_t>(u)] = 1;
            }
        ++sweeps;
        moves += moved;
        if (moved == 0) break;
        double min = INFINITY;
        for (double q : c.sj) min = std::min(min, std::isnan(q) ? -1.0 : q);
        if (min > best_min + 1e-4) {
            best_min = min;
            best_sweep = sweeps;
        } else if (sweeps - best_sweep >= kStallSweeps) {
            break;
        }
    }
    return moves;
}

}  // namespace dualhex::mesher::detail
