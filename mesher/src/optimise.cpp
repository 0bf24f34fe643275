// The optimise stage (optimise.hpp): the driver and phase 1, the foldover-free untangler.
#include "dualhex/mesher/optimise.hpp"

#include <limits>

#include <algorithm>
#include <cmath>

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
    while (sweep < max_sweeps && !c.out_of_time()) {
        for (std::size_t v : vertices) (void)energy_step(c, energy, v);
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

OptimiseResult optimise_mesh(geometry::HexMesh& mesh, const VertexConstraints& constraints, const geometry::AabbTree& tree,
                             const FeatureCurves& curves, const OptimiseOptions& options, QualityState& state) {
    check_constraints(constraints, mesh.points.size(), curves);
    OptimiseResult r;
    r.inverted_before = state.inverted;
    r.min_before = geometry::summarize(state.scaled_jacobian).min;
    const VertexDomain domain{tree, curves, constraints};
    const detail::VertexHexes incidence(mesh);
    detail::BarrierEnergy energy(mesh);
    const std::clock_t start = std::clock();
    // No time limit (0, the default): the sweep bounds alone stop it, so the result does not
    // depend on the machine's load. A limit bounds the time and makes it load-dependent.
    const auto budget = options.time_limit_ms > 0
                            ? static_cast<std::clock_t>(std::min(options.time_limit_ms, 1e9) * 1e-3 * CLOCKS_PER_SEC)
                            : std::numeric_limits<std::clock_t>::max() / 4;
    // Phase 1 gets at most half the budget, so phase 2 always has time.
    detail::OptimiseContext c{mesh, domain, incidence, state.scaled_jacobian, start + budget / 2};
    if (state.inverted > 0) {
        const std::vector<Eigen::Vector3d> before = mesh.points;
        const std::vector<double> sj_before = state.scaled_jacobian;
        r.untangle_sweeps = detail::untangle_phase(c, energy, options.untangle_sweeps);
        const std::size_t inverted = count_inverted(state.scaled_jacobian);
        const double min = geometry::summarize(state.scaled_jacobian).min;
        r.untangle_kept = inverted <= r.inverted_before && min >= r.min_before;  // the contract, both ways
        if (r.untangle_kept) {
            state.inverted = inverted;
        } else {
            mesh.points = before;
            state.scaled_jacobian = sj_before;
        }
    }
    energy.eps = 1e-3;
    r.hit_time_limit = c.out_of_time();
    c.deadline = start + budget;
    r.moves = detail::quality_phase(c, energy, options.min_quality, options.quality_sweeps, r.quality_sweeps);
    state.inverted = count_inverted(state.scaled_jacobian);
    r.inverted_after = state.inverted;
    r.min_after = geometry::summarize(state.scaled_jacobian).min;
    r.reached_target = r.min_after >= options.min_quality;
    r.hit_time_limit = r.hit_time_limit || c.out_of_time();
    return r;
}

}  // namespace dualhex::mesher
