// `Coarse` near the root surface (compositional_weak_root_stars.hpp,
// run_weak_near_root_stars; proofs/README.md W13 (f)): W9's stars with root planes that do
// not pass through v but cut what its leaves' enumeration names.
#include <atomic>
#include <bit>
#include <mutex>
#include <optional>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "dualhex/checkers/compositional_weak_root_stars.hpp"
#include "weak_star_pair.hpp"
#include "window_check.hpp"

namespace dualhex {
namespace {

using namespace weak_stars;

// Root planes: per axis at most one below v (x_a = lo, the root above it) and one above
// (x_a = hi, the root below it): a small root has both within reach.
struct Planes {
    std::array<std::optional<std::int64_t>, 3> lo, hi;
    // The cell (level m + k) lies beyond a plane: cells never straddle one (planes are on the
    // level-(m-1) lattice and the statuses named have level >= m - 1).
    bool outside(const Status& x, std::int64_t unit) const {
        const std::int64_t S = cell_size(unit, x.first);
        for (std::size_t a = 0; a < 3; ++a) {
            if (lo[a] && (x.second[a] + 1) * S <= *lo[a]) return true;
            if (hi[a] && x.second[a] * S >= *hi[a]) return true;
        }
        return false;
    }
    int count() const {
        int n = 0;
        for (std::size_t a = 0; a < 3; ++a) n += (lo[a] ? 1 : 0) + (hi[a] ? 1 : 0);
        return n;
    }
    std::string describe() const {
        std::ostringstream os;
        for (std::size_t a = 0; a < 3; ++a) {
            os << " axis" << a << '[';
            if (lo[a]) os << *lo[a];
            os << ',';
            if (hi[a]) os << *hi[a];
            os << ']';
        }
        return os.str();
    }
};

bool symmetric(const std::array<int, 8>& levels, unsigned axes) {
    for (int a = 0; a < 3; ++a)
        if ((axes >> a) & 1U)
            for (int s = 0; s < 8; ++s)
                if (levels[static_cast<std::size_t>(s)] != levels[static_cast<std::size_t>(s ^ (1 << a))]) return false;
    return true;
}

bool at_v(const LatticePoint& q) { return q == LatticePoint{}; }
bool away_from_v(const CellComplex& cx, std::span<const VertexHandle> loop) {
    return std::none_of(loop.begin(), loop.end(), [&](VertexHandle h) { return at_v(cx.position(h)); });
}

}  // namespace

WeakNearRootStarCheck run_weak_near_root_stars(const TransitionRule& rule, const ElementLibrary& library,
                                               const WeakStarInfluence& inf, const WeakNearRootStarOptions& options) {
    WeakNearRootStarCheck result;
    result.rule = rule.name();
    std::map<LatticePoint, std::size_t> index;
    for (std::size_t q = 0; q < inf.positions.size(); ++q) index[inf.positions[q].position] = q;
    const PieceCubes cubes = piece_cubes(inf);
    const std::int64_t E = cell_size(inf.unit, 0), half = E / 2;
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    std::mutex tally;
    std::atomic<long> failed{0};
    for (int t = 0; t < 8; ++t) {
        if (!((options.parities >> t) & 1U)) continue;
        const std::array<int, 3> parity{t & 1, (t >> 1) & 1, (t >> 2) & 1};
        const LatticePoint g = LatticePoint{parity[0], parity[1], parity[2]} * E;
        const std::set<LatticePoint> cands = candidates(inf, g, half);
        const std::vector<LatticePoint> vertices(cands.begin(), cands.end());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size()), [&](const auto& range) {
            WeakNearRootStarCheck local;
            auto& cache = caches.local();
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                if (options.stop_after > 0 && failed.load() >= options.stop_after) break;
                const LatticePoint& v = vertices[i];
                unsigned surface_axes = 0;  // axes where a root plane can pass through v
                for (int a = 0; a < 3; ++a)
                    if (v[a] == 0 && parity[static_cast<std::size_t>(a)] == 0) surface_axes |= 1U << a;
                Configurations(v, inf.unit).each([&](const std::array<int, 8>& levels, const std::array<weak_stars::Leaf, 8>& leaves) {
                    for (unsigned through = surface_axes;; through = (through - 1) & surface_axes) {
                        if (symmetric(levels, through))
                            for (unsigned minus = through;; minus = (minus - 1) & through) {
                                Planes base;  // the planes through v
                                RootSides sides{};
                                for (std::size_t a = 0; a < 3; ++a) {
                                    if (!((through >> a) & 1U)) continue;
                                    sides[a] = (minus >> a) & 1U ? -1 : 1;
                                    (sides[a] > 0 ? base.lo[a] : base.hi[a]) = 0;
                                }
                                std::vector<weak_stars::Leaf> inside;
                                for (int s = 0; s < 8; ++s) {
                                    bool in = true;
                                    for (int a = 0; a < 3; ++a)
                                        if (sides[static_cast<std::size_t>(a)] != 0) in = in && (((s >> a) & 1) != 0) == (sides[static_cast<std::size_t>(a)] > 0);
                                    if (in) inside.push_back(leaves[static_cast<std::size_t>(s)]);
                                }
                                // Run the enumeration with `planes`; false if no named cell is outside beyond the base.
                                const auto run = [&](const Planes& planes, bool check) {
                                    bool hit = false;
                                    StatusModel model;
                                    model.outside = [&](const Status& x) {
                                        if (!planes.outside(x, inf.unit)) return false;
                                        if (!base.outside(x, inf.unit)) hit = true;
                                        return true;
                                    };
                                    Forcing forced(inside, model.outside);
                                    const Pair p = split(inf, index, v, g, inside, forced, model);
                                    if (!hit || !check) return hit;
                                    const auto fail = [&](const std::string& why) {
                                        ++local.failed;
                                        ++failed;
                                        if (local.failures.size() < 10) {
                                            std::ostringstream os;
                                            os << "g=(" << parity[0] << parity[1] << parity[2] << ") v-g=" << v - g << " planes";
                                            os << planes.describe();
                                            os << " levels";
                                            for (int l : levels) os << ' ' << l;
                                            os << ": " << why;
                                            local.failures.push_back(os.str());
                                        }
                                    };
                                    Stars stars;
                                    try {
                                        stars = stars_by_search(cubes, p, local.search_nodes, options.search_limit);
                                    } catch (const SearchTooLarge& e) {
                                        if (through == 0 && is_corner_pair(inf, p, v)) {  // W11, as in run_weak_stars
                                            try {
                                                const CornerCheck c = check_corner_pair(inf, rule, cache, cubes, p, v, options.search_limit);
                                                local.search_nodes += c.search_nodes;
                                                if (c.passed) ++local.corner_pairs;
                                                else fail("corner pair (W11): " + c.defect);
                                            } catch (const std::exception& e2) {
                                                fail(std::string("corner pair (W11): ") + e2.what());
                                            }
                                        } else {
                                            fail(e.what());
                                        }
                                        return hit;
                                    }
                                    for (const auto& [pieces, contexts] : stars) {
                                        if (std::all_of(pieces.begin(), pieces.end(), [](int x) { return x == -1; })) {
                                            ++local.empty;
                                            continue;
                                        }
                                        ++local.stars;
                                        try {
                                            const ConfigurationComplex star = build_star(inf, rule, cache, p, v, contexts);
                                            if (through != 0) {
                                                if (const auto why = boundary_vertex_defect(star.complex, sides)) fail(*why);
                                                else ++local.passed;
                                                continue;
                                            }
                                            const ConfigurationReport r = detail::analyse(star, at_v, away_from_v);
                                            if (r.ok() && r.checked_vertices == 1) ++local.passed;
                                            else fail(r.summary());
                                        } catch (const std::exception& e) {
                                            fail(e.what());
                                        }
                                    }
                                    return hit;
                                };
                                // Per axis and side of v, the further plane positions that make a named
                                // cell outside (lo: below v, hi: above).
                                std::array<std::vector<std::int64_t>, 3> lo_hits, hi_hits;
                                for (std::size_t a = 0; a < 3; ++a)
                                    for (std::int64_t j = -options.reach; j <= options.reach; ++j) {
                                        const std::int64_t P = g[static_cast<int>(a)] + j * E;
                                        if (P % (2 * E) != 0 || P == v[static_cast<int>(a)]) continue;
                                        const bool below = P < v[static_cast<int>(a)];
                                        if ((below ? base.lo[a] : base.hi[a])) continue;  // a plane through v on that side
                                        Planes planes = base;
                                        (below ? planes.lo[a] : planes.hi[a]) = P;
                                        if (!run(planes, false)) {
                                            ++local.unchanged;
                                            continue;
                                        }
                                        if (std::abs(j) >= options.reach - 1) ++local.hits_at_reach;
                                        (below ? lo_hits[a] : hi_hits[a]).push_back(P);
                                    }
                                // Every combination of them (at least one, at most max_planes): per
                                // axis and side none or one of its positions.
                                std::array<std::size_t, 6> at{};  // 0: none, else position index + 1
                                const auto list = [&](std::size_t d) -> const std::vector<std::int64_t>& { return d % 2 ? hi_hits[d / 2] : lo_hits[d / 2]; };
                                for (bool more = true; more;) {
                                    Planes planes = base;
                                    for (std::size_t d = 0; d < 6; ++d)
                                        if (at[d] > 0) (d % 2 ? planes.hi[d / 2] : planes.lo[d / 2]) = list(d)[at[d] - 1];
                                    const int n = planes.count() - base.count();
                                    if (n > 0 && n <= options.max_planes) {
                                        ++local.combinations[static_cast<std::size_t>(std::popcount(through))];
                                        run(planes, true);
                                    }
                                    more = false;
                                    for (std::size_t d = 0; d < 6 && !more; ++d) {
                                        if (++at[d] <= list(d).size()) more = true;
                                        else at[d] = 0;
                                    }
                                }
                                if (minus == 0) break;
                            }
                        if (through == 0) break;
                    }
                });
            }
            const std::lock_guard lock(tally);
            for (std::size_t k = 0; k < 4; ++k) result.combinations[k] += local.combinations[k];
            result.unchanged += local.unchanged;
            result.stars += local.stars;
            result.empty += local.empty;
            result.passed += local.passed;
            result.failed += local.failed;
            result.search_nodes += local.search_nodes;
            result.corner_pairs += local.corner_pairs;
            result.hits_at_reach += local.hits_at_reach;
            for (auto& f : local.failures)
                if (result.failures.size() < 10) result.failures.push_back(std::move(f));
        });
    }
    return result;
}

}  // namespace dualhex
