// The optimise stage (optimise.hpp): the driver and phase 1, the foldover-free untangler.
#include "dualhex/mesher/optimise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Cholesky>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "optimise_detail.hpp"

namespace dualhex::mesher {
namespace detail {

LocalQuality local_quality(const OptimiseContext& c, std::size_t v, const Eigen::Vector3d& x) {
    Eigen::Vector3d& p = c.mesh.points[v];
    const Eigen::Vector3d keep = p;
    p = x;
    LocalQuality q;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i) {
        const double s = geometry::scaled_jacobian(c.mesh, static_cast<std::size_t>(c.incidence.hex[i]));
        if (!(s > 0)) ++q.inverted;
        q.min = std::min(q.min, std::isnan(s) ? -1.0 : s);
    }
    p = keep;
    return q;
}

void move_vertex(OptimiseContext& c, std::size_t v, const Eigen::Vector3d& x) {
    c.mesh.points[v] = x;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i) {
        const auto h = static_cast<std::size_t>(c.incidence.hex[i]);
        c.sj[h] = geometry::scaled_jacobian(c.mesh, h);
    }
}

double local_size(const OptimiseContext& c, const BarrierEnergy& energy, std::size_t v) {
    double sum = 0;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        sum += 1.0 / energy.scale[static_cast<std::size_t>(c.incidence.hex[i])];
    return c.incidence.count(v) ? sum / static_cast<double>(c.incidence.count(v)) : 0.0;
}

namespace {

// The vertices of the inverted hexes, grown by `rings` vertex rings through hexes.
std::vector<std::size_t> near_inverted(const OptimiseContext& c, int rings, std::vector<char>& hex_active) {
    std::vector<char> in(c.mesh.points.size(), 0);
    hex_active.assign(c.mesh.hexes.size(), 0);
    for (std::size_t h = 0; h < c.sj.size(); ++h)
        if (!(c.sj[h] > 0)) hex_active[h] = 1;
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

double local_energy(const OptimiseContext& c, const BarrierEnergy& e, std::size_t v, const Eigen::Vector3d& x,
                    Eigen::Vector3d* gradient) {
    if (gradient) gradient->setZero();
    double sum = 0;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        sum += e.hex(c.mesh, static_cast<std::size_t>(c.incidence.hex[i]), static_cast<int>(v), x, gradient);
    return sum;
}

// The Newton direction of v's local energy at x: H d = -g, H by forward differences of
// the analytic gradient (symmetrised), shifted until positive definite; the gradient
// direction if that fails.
Eigen::Vector3d newton_direction(const OptimiseContext& c, const BarrierEnergy& e, std::size_t v,
                                 const Eigen::Vector3d& x, const Eigen::Vector3d& g, double size) {
    const double delta = 1e-5 * size;
    Eigen::Matrix3d H;
    for (int a = 0; a < 3; ++a) {
        Eigen::Vector3d y = x, ga;
        y[a] += delta;
        (void)local_energy(c, e, v, y, &ga);
        H.col(a) = (ga - g) / delta;
    }
    H = 0.5 * (H + H.transpose()).eval();
    double shift = 0;
    for (int attempt = 0; attempt < 8; ++attempt) {
        const Eigen::LLT<Eigen::Matrix3d> llt(H + shift * Eigen::Matrix3d::Identity());
        if (llt.info() == Eigen::Success) return llt.solve(-g);
        shift = shift == 0 ? 1e-6 * H.diagonal().cwiseAbs().maxCoeff() + 1e-12 : shift * 10;
    }
    return -g;
}

// One damped Newton step of v on its local energy (restricted to v's domain, at most one
// local size long, halved until the energy decreases); true if v moved.
bool energy_step(OptimiseContext& c, const BarrierEnergy& e, std::size_t v) {
    const Eigen::Vector3d x = c.mesh.points[v];
    Eigen::Vector3d g;
    const double e0 = local_energy(c, e, v, x, &g);
    const double size = local_size(c, e, v);
    if (!(g.norm() > 0)) return false;
    Eigen::Vector3d d = c.domain.restrict(v, x, newton_direction(c, e, v, x, g, size));
    if (!(d.dot(g) < 0)) d = c.domain.restrict(v, x, -g);  // not a descent direction: the gradient
    const double len = d.norm();
    if (!(len > 0)) return false;
    if (len > size) d *= size / len;
    for (int halving = 0; halving < 12; ++halving, d *= 0.5) {
        const Eigen::Vector3d y = c.domain.project(v, x + d, x);
        if (local_energy(c, e, v, y, nullptr) < e0) {
            move_vertex(c, v, y);
            return true;
        }
    }
    return false;
}

double chi(double d, double eps) { return 0.5 * (d + std::sqrt(eps * eps + d * d)); }

}  // namespace

int untangle_phase(OptimiseContext& c, BarrierEnergy& energy, int max_sweeps) {
    std::vector<char> hex_active;
    int rings = 2;
    std::vector<std::size_t> vertices = near_inverted(c, rings, hex_active);
    auto totals = [&](double& min_det) {
        double sum = 0;
        min_det = INFINITY;
        for (std::size_t h = 0; h < hex_active.size(); ++h)
            if (hex_active[h]) {
                sum += energy.hex(c.mesh, h, -1, Eigen::Vector3d::Zero(), nullptr);
                min_det = std::min(min_det, energy.min_det(c.mesh, h));
            }
        return sum;
    };
    double min_det = 0;
    double e_prev = totals(min_det);
    energy.eps = min_det < 0 ? 2 * std::sqrt(0.1 * (0.1 - min_det)) : 1e-3;
    constexpr int kStallSweeps = 25, kMaxRings = 4;
    std::size_t best_inverted = count_inverted(c.sj);
    int best_sweep = 0, sweep = 0;
    while (sweep < max_sweeps && !c.stopped()) {
        for (std::size_t v : vertices) {
            if (!c.take_visit()) break;
            (void)energy_step(c, energy, v);
        }
        ++sweep;
        const double e = totals(min_det);
        const std::size_t inverted = count_inverted(c.sj);
        if (inverted == 0) break;
        if (inverted < best_inverted) {
            best_inverted = inverted;
            best_sweep = sweep;
        } else if (sweep - best_sweep >= kStallSweeps) {
            if (rings >= kMaxRings) break;  // no fewer inverted hexes for a while: leave the rest to phase 2
            // Stalled: free a wider region around what is still inverted, start a new eps schedule.
            vertices = near_inverted(c, ++rings, hex_active);
            best_sweep = sweep;
            e_prev = totals(min_det);
            energy.eps = 2 * std::sqrt(0.1 * (0.1 - std::min(min_det, 0.0)));
            continue;
        }
        // The paper's eps update: follow the energy decrease, stay ahead of the worst det.
        const double sigma = std::max(1.0 - e / e_prev, 0.1);
        const double mu = (1 - sigma) * chi(min_det, energy.eps);
        energy.eps = min_det < mu ? 2 * std::sqrt(mu * (mu - min_det)) : 1e-10;
        e_prev = e;
    }
    return sweep;
}

}  // namespace detail

namespace {

// Phase 1 from the current state, kept if it leaves fewer inverted hexes, or as many and no
// lower a minimum (else the points are restored); returns its sweeps. Fewer inverted hexes
// may come with a lower minimum of the remaining ones: the whole optimiser's contract is
// kept by optimise_mesh's final check.
int untangle_kept(detail::OptimiseContext& c, detail::BarrierEnergy& energy, int max_sweeps, QualityState& state,
                  bool& kept) {
    const std::vector<Eigen::Vector3d> before = c.mesh.points;
    const std::vector<double> sj_before = state.scaled_jacobian;
    const std::size_t inverted_before = state.inverted;
    const double min_before = geometry::summarize(sj_before).min;
    const int sweeps = detail::untangle_phase(c, energy, max_sweeps);
    const std::size_t inverted = count_inverted(state.scaled_jacobian);
    kept = inverted < inverted_before ||
           (inverted == inverted_before && geometry::summarize(state.scaled_jacobian).min >= min_before);
    if (kept) {
        state.inverted = inverted;
    } else {
        c.mesh.points = before;
        state.scaled_jacobian = sj_before;
    }
    return sweeps;
}

}  // namespace

OptimiseResult optimise_mesh(geometry::HexMesh& mesh, const VertexConstraints& constraints, const geometry::AabbTree& tree,
                             const FeatureCurves& curves, const OptimiseOptions& options, QualityState& state) {
    check_constraints(constraints, mesh.points.size(), curves);
    OptimiseResult r;
    r.inverted_before = state.inverted;
    r.min_before = geometry::summarize(state.scaled_jacobian).min;
    const std::vector<Eigen::Vector3d> start = mesh.points;  // for the final contract check
    const QualityState start_state = state;
    const VertexDomain domain{tree, curves, constraints};
    const detail::VertexHexes incidence(mesh);
    detail::BarrierEnergy energy(mesh);
    const double visits = options.work_per_vertex * static_cast<double>(mesh.points.size());
    r.work_budget = options.work_per_vertex > 0 ? static_cast<std::size_t>(std::max(1.0, std::min(visits, 1e18))) : 0;
    const std::size_t budget = r.work_budget > 0 ? r.work_budget : std::numeric_limits<std::size_t>::max();
    detail::OptimiseContext c{mesh, domain, incidence, state.scaled_jacobian, 0};
    if (options.time_limit_ms > 0) {
        c.timed = true;
        c.deadline = std::chrono::steady_clock::now() +
                     std::chrono::microseconds(static_cast<std::int64_t>(std::min(options.time_limit_ms, 1e9) * 1e3));
    }
    // Rounds of untangling then quality moves: the quality phase often frees what the
    // untangler stalled on (thin pad hexes on concave spots), so while hexes stay inverted
    // and a round removed some, another follows. Each phase of a round with inverted hexes
    // gets at most half of what is left of the budget, so the next always has some.
    constexpr int kRounds = 4;
    for (int round = 0; round < kRounds && !c.hit_time; ++round) {
        const std::size_t inverted_at_start = state.inverted;
        auto half_of_rest = [&] { return budget == std::numeric_limits<std::size_t>::max() ? budget
                                                                                          : c.work + (budget - c.work + 1) / 2; };
        if (state.inverted > 0) {
            c.work_limit = half_of_rest();
            bool kept = false;
            r.untangle_sweeps += untangle_kept(c, energy, options.untangle_sweeps, state, kept);
            r.untangle_kept = r.untangle_kept || kept;
        }
        energy.eps = 1e-3;
        c.hit_budget = false;  // a phase's share spent is not the budget spent
        c.work_limit = state.inverted > 0 && round + 1 < kRounds ? half_of_rest() : budget;
        int sweeps = 0;
        r.moves += detail::quality_phase(c, energy, options.min_quality, options.quality_sweeps, sweeps);
        r.quality_sweeps += sweeps;
        state.inverted = count_inverted(state.scaled_jacobian);
        if (state.inverted == 0 || state.inverted >= inverted_at_start || c.work >= budget) break;
    }
    r.work = c.work;
    // Each rescue has its own budget (work_per_vertex per region vertex), and runs only while
    // the main budget is not spent, so a starved run stays starved.
    for (int rescue = 0; rescue < options.rescue_rounds && state.inverted > 0 && !c.hit_time && c.work < budget;
         ++rescue) {
        std::vector<std::size_t> inverted;
        for (std::size_t h = 0; h < state.scaled_jacobian.size(); ++h)
            if (!(state.scaled_jacobian[h] > 0)) inverted.push_back(h);
        OptimiseOptions local = options;
        local.rescue_rounds = 0;
        local.time_limit_ms = c.timed ? std::max(1e-3, std::chrono::duration<double, std::milli>(
                                                            c.deadline - std::chrono::steady_clock::now()).count())
                                      : 0;
        const OptimiseResult lr = optimise_region(mesh, inverted, 2 + rescue, constraints, tree, curves, local);
        r.work += lr.work;
        r.hit_time_limit = r.hit_time_limit || lr.hit_time_limit;
        state = quality_state(mesh);  // the region's contract keeps the whole mesh's
    }
    // The contract: never more inverted hexes, never a lower minimum than at the start.
    if (state.inverted > r.inverted_before || geometry::summarize(state.scaled_jacobian).min < r.min_before) {
        mesh.points = start;
        state = start_state;
    }
    r.inverted_after = state.inverted;
    r.min_after = geometry::summarize(state.scaled_jacobian).min;
    r.reached_target = r.min_after >= options.min_quality;
    r.hit_work_budget = c.work >= budget;
    r.hit_time_limit = r.hit_time_limit || c.hit_time;
    return r;
}

}  // namespace dualhex::mesher
