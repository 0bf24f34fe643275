#pragma once
// Internal to the optimise stage: what its two phases share.
#include <algorithm>
#include <chrono>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "dualhex/geometry/hex_output.hpp"
#include "dualhex/mesher/constrained_position.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "hex_energy.hpp"

namespace dualhex::mesher::detail {

struct OptimiseContext {
    geometry::HexMesh& mesh;
    const VertexDomain& domain;
    const VertexHexes& incidence;
    std::vector<double>& sj;  ///< (hexes) kept current by every accepted move
    double bad_below;         ///< OptimiseOptions::bad_below
    std::size_t work_limit;   ///< vertex visits allowed so far (the current phase's share)
    std::size_t work = 0;     ///< vertex visits done
    bool timed = false;       ///< the opt-in wall-clock bound is on
    std::chrono::steady_clock::time_point deadline{};
    bool hit_budget = false, hit_time = false;

    /// Takes one vertex visit from the budget; false (and nothing taken) if it is spent or
    /// the wall-clock bound passed. Counting visits, not time, keeps the output deterministic.
    [[nodiscard]] bool take_visit() {
        if (work >= work_limit) return !(hit_budget = true);
        if (timed && std::chrono::steady_clock::now() > deadline) return !(hit_time = true);
        ++work;
        return true;
    }
    [[nodiscard]] bool stopped() const { return hit_budget || hit_time; }
};

/// The hexes the phases work on: scaled Jacobian <= bad_below (OptimiseOptions) or NaN.
[[nodiscard]] inline bool is_bad(double sj, double bad_below) { return !(sj > bad_below); }
[[nodiscard]] inline std::size_t count_bad(const std::vector<double>& sj, double bad_below) {
    return static_cast<std::size_t>(std::count_if(sj.begin(), sj.end(), [&](double s) { return is_bad(s, bad_below); }));
}

/// Of the hexes at v, with v at x: how many are inverted (<= 0 or NaN), how many bad
/// (is_bad), their minimum SJ; compared in that order, so a flat hex is never bought with
/// an inverted one.
struct LocalQuality {
    std::size_t inverted = 0, bad = 0;
    double min = 1;
    [[nodiscard]] bool better_than(const LocalQuality& o) const {
        if (inverted != o.inverted) return inverted < o.inverted;
        if (bad != o.bad) return bad < o.bad;
        return min > o.min + 1e-12;
    }
};
[[nodiscard]] LocalQuality local_quality(const OptimiseContext& c, std::size_t v, const Eigen::Vector3d& x);
/// Counts one hex of scaled Jacobian s into q (as local_quality does).
void count_hex(LocalQuality& q, double s, double bad_below);

/// local_quality(c, v, x) for many trial positions x of one vertex v, bit for bit: of each
/// hex at v, the corner terms whose tet does not read v are computed once here, so a trial
/// costs only the terms that do (4 of the 8 on a hex with distinct vertices), folded in corner
/// order as geometry::scaled_jacobian folds them. Valid while no other vertex moves.
class VertexStarQuality {
public:
    VertexStarQuality(const OptimiseContext& c, std::size_t v);
    [[nodiscard]] LocalQuality at(const Eigen::Vector3d& x) const;

private:
    struct HexTerms {
        std::size_t hex = 0;
        std::uint8_t reads_v = 0;                 // bit k: corner k's tet has v
        std::array<std::optional<double>, 8> term;  // the others' terms (geometry/quality.hpp)
    };
    const OptimiseContext& c_;
    std::size_t v_;
    std::vector<HexTerms> hexes_;
};

/// Moves v to x and refreshes sj of its hexes.
void move_vertex(OptimiseContext& c, std::size_t v, const Eigen::Vector3d& x);

/// The optimiser's contract, checked once on the whole result: if `state` has more inverted
/// hexes or a lower minimum than `start_state`, the points go back to `start` and the state
/// to `start_state`; true if they did.
bool restore_if_worse(geometry::HexMesh& mesh, const std::vector<Eigen::Vector3d>& start, const QualityState& start_state,
                      QualityState& state);

/// Mean edge length of the hexes at v (the step scale).
[[nodiscard]] double local_size(const OptimiseContext& c, const BarrierEnergy& energy, std::size_t v);

/// Phase 1 (optimise.hpp); returns sweeps done.
int untangle_phase(OptimiseContext& c, BarrierEnergy& energy, int max_sweeps);
/// Phase 2 (optimise.hpp); returns accepted moves, sweeps done in `sweeps`.
std::size_t quality_phase(OptimiseContext& c, BarrierEnergy& energy, double target, int max_sweeps, int& sweeps);

}  // namespace dualhex::mesher::detail
