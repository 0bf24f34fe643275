// The optimise stage (optimise.hpp): the driver, what the phases share, the final contract.
#include "dualhex/mesher/optimise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

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
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        count_hex(q, geometry::scaled_jacobian(c.mesh, static_cast<std::size_t>(c.incidence.hex[i])), c.bad_below);
    p = keep;
    return q;
}

void count_hex(LocalQuality& q, double s, double bad_below) {
    if (!(s > 0)) ++q.inverted;
    if (is_bad(s, bad_below)) ++q.bad;
    q.min = std::min(q.min, std::isnan(s) ? -1.0 : s);
}

void move_vertex(OptimiseContext& c, std::size_t v, const Eigen::Vector3d& x) {
    c.mesh.points[v] = x;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i) {
        const auto h = static_cast<std::size_t>(c.incidence.hex[i]);
        c.sj[h] = geometry::scaled_jacobian(c.mesh, h);
    }
}

bool restore_if_worse(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& start, const QualityState& start_state,
                      QualityState& state) {
    const bool worse = state.inverted > start_state.inverted ||
                       geometry::summarize(state.scaled_jacobian).min < geometry::summarize(start_state.scaled_jacobian).min;
    if (worse) {
        mesh.points = start;
        state = start_state;
    }
    return worse;
}

double local_size(const OptimiseContext& c, const BarrierEnergy& energy, std::size_t v) {
    double sum = 0;
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i)
        sum += 1.0 / energy.scale[static_cast<std::size_t>(c.incidence.hex[i])];
    return c.incidence.count(v) ? sum / static_cast<double>(c.incidence.count(v)) : 0.0;
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
    const std::size_t bad_before = detail::count_bad(sj_before, c.bad_below);
    const double min_before = geometry::summarize(sj_before).min;
    const int sweeps = detail::untangle_phase(c, energy, max_sweeps);
    const std::size_t bad = detail::count_bad(state.scaled_jacobian, c.bad_below);
    const std::size_t inverted = count_inverted(state.scaled_jacobian);
    kept = inverted < state.inverted ||
           (inverted == state.inverted &&
            (bad < bad_before || (bad == bad_before && geometry::summarize(state.scaled_jacobian).min >= min_before)));
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
    detail::OptimiseContext c{mesh, domain, incidence, state.scaled_jacobian, options.bad_below, 0};
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
        const std::size_t bad_at_start = detail::count_bad(state.scaled_jacobian, c.bad_below);
        auto half_of_rest = [&] { return budget == std::numeric_limits<std::size_t>::max() ? budget
                                                                                          : c.work + (budget - c.work + 1) / 2; };
        if (bad_at_start > 0) {
            c.work_limit = half_of_rest();
            bool kept = false;
            r.untangle_sweeps += untangle_kept(c, energy, options.untangle_sweeps, state, kept);
            r.untangle_kept = r.untangle_kept || kept;
        }
        energy.eps = 1e-3;
        c.hit_budget = false;  // a phase's share spent is not the budget spent
        c.work_limit = bad_at_start > 0 && round + 1 < kRounds ? half_of_rest() : budget;
        int sweeps = 0;
        r.moves += detail::quality_phase(c, energy, options.min_quality, options.quality_sweeps, sweeps);
        r.quality_sweeps += sweeps;
        state.inverted = count_inverted(state.scaled_jacobian);
        const std::size_t bad = detail::count_bad(state.scaled_jacobian, c.bad_below);
        if (bad == 0 || bad >= bad_at_start || c.work >= budget) break;
    }
    r.work = c.work;
    // Each rescue has its own budget (work_per_vertex per region vertex), and runs only while
    // the main budget is not spent, so a starved run stays starved.
    for (int rescue = 0; rescue < options.rescue_rounds && detail::count_bad(state.scaled_jacobian, c.bad_below) > 0 && !c.hit_time && c.work < budget;
         ++rescue) {
        std::vector<std::size_t> inverted;
        for (std::size_t h = 0; h < state.scaled_jacobian.size(); ++h)
            if (detail::is_bad(state.scaled_jacobian[h], c.bad_below)) inverted.push_back(h);
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
    r.restored = detail::restore_if_worse(mesh, start, start_state, state);
    r.inverted_after = state.inverted;
    r.min_after = geometry::summarize(state.scaled_jacobian).min;
    r.reached_target = r.min_after >= options.min_quality;
    r.hit_work_budget = c.work >= budget;
    r.hit_time_limit = r.hit_time_limit || c.hit_time;
    return r;
}

}  // namespace dualhex::mesher
