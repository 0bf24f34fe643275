// Phase 1 of the optimise stage (optimise.hpp): the foldover-free untangler of Garanzha et
// al. 2021 (hex_energy.hpp), Gauss-Seidel sweeps of per-vertex Newton steps with the
// paper's eps continuation.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>

#include "dualhex/geometry/parallel_each.hpp"
#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "optimise_detail.hpp"

namespace dualhex::mesher::detail {
namespace {

// The vertices of the inverted hexes, grown by `rings` vertex rings through hexes.
std::vector<std::size_t> near_inverted(const OptimiseContext& c, int rings, std::vector<char>& hex_active) {
    std::vector<char> in(c.mesh.points.size(), 0);
    hex_active.assign(c.mesh.hexes.size(), 0);
    for (std::size_t h = 0; h < c.sj.size(); ++h)
        if (is_bad(c.sj[h], c.bad_below)) hex_active[h] = 1;
    for (int r = 0; r <= rings; ++r) {
        for (std::size_t h = 0; h < hex_active.size(); ++h)
            if (hex_active[h])
                for (int v : c.mesh.hexes[h]) in[static_cast<std::size_t>(v)] = 1;
        if (r == rings) break;
        for (std::size_t v = 0; v < in.size(); ++v)
            if (in[v])
                for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
                    hex_active[static_cast<std::size_t>(c.incidence.hex[i])] = 1;
    }
    std::vector<std::size_t> out;
    for (std::size_t v = 0; v < in.size(); ++v)
        if (in[v] && c.domain.role(v) != VertexRole::Corner) out.push_back(v);
    return out;
}

double local_energy(const OptimiseContext& c, const BarrierEnergy& e, std::size_t v, const Eigen::Vector3d& x) {
    double sum = 0;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        sum += e.hex(c.mesh, static_cast<std::size_t>(c.incidence.hex[i]), static_cast<int>(v), x, nullptr);
    return sum;
}

// H d = -g with the exact local Hessian, shifted until positive definite (the barrier's
// Hessian is indefinite where a tet is inverted); the gradient direction if that fails.
Eigen::Vector3d newton_direction(const Eigen::Matrix3d& H, const Eigen::Vector3d& g) {
    double shift = 0;
    for (int attempt = 0; attempt < 8; ++attempt) {
        const Eigen::LLT<Eigen::Matrix3d> llt(H + shift * Eigen::Matrix3d::Identity());
        if (llt.info() == Eigen::Success) return llt.solve(-g);
        shift = shift == 0 ? 1e-6 * H.diagonal().cwiseAbs().maxCoeff() + 1e-12 : shift * 10;
    }
    return -g;
}

// One damped Newton step of v on its local energy (restricted to v's domain, at most one
// local size long, halved until the energy decreases); true if v moved. The hexes' sj is
// left to the caller (refreshed once per sweep).
bool energy_step(OptimiseContext& c, const BarrierEnergy& e, std::size_t v) {
    const Eigen::Vector3d x = c.mesh.points[v];
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    double e0 = 0;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        e0 += e.hex_newton(c.mesh, static_cast<std::size_t>(c.incidence.hex[i]), static_cast<int>(v), x, g, H);
    if (!(g.norm() > 0)) return false;
    const double size = local_size(c, e, v);
    Eigen::Vector3d d = c.domain.restrict(v, x, newton_direction(H, g));
    if (!(d.dot(g) < 0)) d = c.domain.restrict(v, x, -g);  // not a descent direction: the gradient
    const double len = d.norm();
    if (!(len > 0)) return false;
    if (len > size) d *= size / len;
    for (int halving = 0; halving < 12; ++halving, d *= 0.5) {
        const Eigen::Vector3d y = c.domain.project(v, x + d, x);
        if (local_energy(c, e, v, y) < e0) {
            c.mesh.points[v] = y;
            return true;
        }
    }
    return false;
}

// The paper's first eps: sqrt(1e-12 + 0.04 min(min_det, 0)^2).
double initial_eps(double min_det) { return std::sqrt(1e-12 + 0.04 * std::pow(std::min(min_det, 0.0), 2)); }

// The paper's floor of the energy decrease sigma is 0.1, after a full L-BFGS minimisation per
// eps; here each eps gets one Gauss-Seidel sweep, whose relative decrease is small, so the
// floor decides the pace: 0.3 reaches the same untangled states in about half the sweeps of
// 0.1 on the shared surfaces (bunny: 0 inverted after 96 sweeps, against 150).
constexpr double kSigmaFloor = 0.3;

double chi(double d, double eps) { return 0.5 * (d + std::sqrt(eps * eps + d * d)); }

// The best state seen (fewest inverted hexes, then fewest bad ones, then the highest
// minimum): the points and sj to return to.
struct BestState {
    LocalQuality q{SIZE_MAX, SIZE_MAX, -INFINITY};
    std::vector<Eigen::Vector3d> points;
    std::vector<double> sj;
    void offer(const OptimiseContext& c) {
        LocalQuality now{count_inverted(c.sj), count_bad(c.sj, c.bad_below), INFINITY};
        for (double s : c.sj) now.min = std::min(now.min, std::isnan(s) ? -1.0 : s);
        if (!now.better_than(q)) return;
        q = now;
        points = c.mesh.points;
        sj = c.sj;
    }
};

}  // namespace

int untangle_phase(OptimiseContext& c, BarrierEnergy& energy, int max_sweeps) {
    std::vector<char> hex_active, stale(c.mesh.hexes.size(), 0);
    std::vector<std::size_t> moved_hexes;
    int rings = 2;
    std::vector<std::size_t> vertices = near_inverted(c, rings, hex_active);
    // A worklist: a vertex is visited only if a vertex of its hexes moved noticeably in the
    // last sweep, or one of its hexes has a corner det within kNearEps x eps (where the
    // energy still depends on eps); elsewhere its local energy has not changed.
    constexpr double kNearEps = 10, kNoticeable = 1e-3;
    std::vector<char> dirty(c.mesh.points.size(), 1);
    auto mark_hex = [&](std::size_t h) {
        for (int w : c.mesh.hexes[h]) dirty[static_cast<std::size_t>(w)] = 1;
    };
    // The active hexes' energies and worst dets are pure evaluations, made in parallel into
    // one slot per hex; the sum, the minimum and the marks are then taken in hex order, so
    // they are the serial ones bit for bit.
    std::vector<double> hex_energy(c.mesh.hexes.size()), hex_det(c.mesh.hexes.size());
    auto totals = [&](double& min_det, bool mark) {
        geometry::parallel_each(hex_active.size(), 512, [&](std::size_t h) {
            if (!hex_active[h]) return;
            hex_energy[h] = energy.hex(c.mesh, h, -1, Eigen::Vector3d::Zero(), nullptr);
            hex_det[h] = energy.min_det(c.mesh, h);
        });
        double sum = 0;
        min_det = INFINITY;
        for (std::size_t h = 0; h < hex_active.size(); ++h)
            if (hex_active[h]) {
                sum += hex_energy[h];
                min_det = std::min(min_det, hex_det[h]);
                if (mark && !(hex_det[h] > kNearEps * energy.eps)) mark_hex(h);
            }
        return sum;
    };
    double min_det = 0;
    (void)totals(min_det, false);
    energy.eps = initial_eps(min_det);
    constexpr int kStallSweeps = 25, kMaxRings = 4;
    BestState best;
    best.offer(c);
    std::size_t fewest = best.q.bad;
    int best_sweep = 0, sweep = 0;
    while (sweep < max_sweeps && !c.stopped()) {
        double unused = 0;
        const double e_before = totals(unused, true);  // at this eps: the paper's E_prev
        std::vector<char> next(c.mesh.points.size(), 0);
        for (std::size_t v : vertices) {
            if (!dirty[v]) continue;
            if (!c.take_visit()) break;
            const Eigen::Vector3d x = c.mesh.points[v];
            if (!energy_step(c, energy, v)) continue;
            const bool noticeable = (c.mesh.points[v] - x).norm() > kNoticeable * local_size(c, energy, v);
            for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i) {
                const auto h = static_cast<std::size_t>(c.incidence.hex[i]);
                if (!stale[h]) moved_hexes.push_back(h);
                stale[h] = 1;
                if (noticeable)
                    for (int w : c.mesh.hexes[h]) next[static_cast<std::size_t>(w)] = 1;
            }
        }
        dirty.swap(next);
        for (std::size_t h : moved_hexes) {
            c.sj[h] = geometry::scaled_jacobian(c.mesh, h);
            stale[h] = 0;
        }
        moved_hexes.clear();
        ++sweep;
        const double e = totals(min_det, false);
        const std::size_t inverted = count_bad(c.sj, c.bad_below);
        best.offer(c);
        if (inverted == 0) break;
        if (inverted < fewest) {
            fewest = inverted;
            best_sweep = sweep;
        } else if (sweep - best_sweep >= kStallSweeps) {
            if (rings >= kMaxRings) break;  // no fewer inverted hexes for a while: leave the rest to phase 2
            // Stalled: from the best state, free a wider region around what is still
            // inverted, start a new eps schedule.
            c.mesh.points = best.points;
            c.sj = best.sj;
            vertices = near_inverted(c, ++rings, hex_active);
            best_sweep = sweep;
            (void)totals(min_det, false);
            energy.eps = initial_eps(min_det);
            continue;
        }
        // The paper's eps update: follow the energy decrease, stay ahead of the worst det.
        const double sigma = std::max(1.0 - e / e_before, kSigmaFloor);
        const double mu = (1 - sigma) * chi(min_det, energy.eps);
        energy.eps = min_det < mu ? 2 * std::sqrt(mu * (mu - min_det)) : 1e-10;
    }
    c.mesh.points = best.points;
    c.sj = best.sj;
    return sweep;
}

}  // namespace dualhex::mesher::detail
