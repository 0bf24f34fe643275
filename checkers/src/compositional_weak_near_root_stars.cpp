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

// What every run shares, and one thread's tally.
struct Shared {
    const TransitionRule& rule;
    const WeakStarInfluence& inf;
    const WeakNearRootStarOptions& options;
    std::map<LatticePoint, std::size_t> index;
    PieceCubes cubes;
    std::atomic<long> failed{0};
};

// One (vertex, configuration) with a choice of root planes through v (the base, as in
// run_weak_root_stars; none when v is inside) and the runs with further planes.
class Base {
public:
    Base(Shared& shared, WeakNearRootStarCheck& tally, detail::TemplateCache& cache, const LatticePoint& v, const LatticePoint& g,
         const std::array<int, 8>& levels, const std::array<weak_stars::Leaf, 8>& leaves, const RootSides& sides)
        : s_(shared), tally_(tally), cache_(cache), v_(v), g_(g), levels_(levels), sides_(sides) {
        for (std::size_t a = 0; a < 3; ++a)
            if (sides[a] != 0) (sides[a] > 0 ? planes_.lo[a] : planes_.hi[a]) = 0;
        for (int o = 0; o < 8; ++o) {
            bool in = true;  // on the root side of every plane through v
            for (int a = 0; a < 3; ++a)
                if (sides[static_cast<std::size_t>(a)] != 0) in = in && (((o >> a) & 1) != 0) == (sides[static_cast<std::size_t>(a)] > 0);
            if (in) inside_.push_back(leaves[static_cast<std::size_t>(o)]);
        }
    }

    // Every further plane that changes the run alone, then every combination of them.
    void run() {
        std::array<std::vector<std::int64_t>, 6> hits;  // per axis and side of v (2a: below, 2a + 1: above)
        const std::int64_t E = cell_size(s_.inf.unit, 0);
        for (int a = 0; a < 3; ++a)
            for (std::int64_t j = -s_.options.reach; j <= s_.options.reach; ++j) {
                const std::int64_t P = g_[a] + j * E;
                if (P % (2 * E) != 0 || P == v_[a]) continue;  // root planes: even level-m coordinates
                const std::size_t d = 2 * static_cast<std::size_t>(a) + (P > v_[a] ? 1 : 0);
                if (slot(planes_, d)) continue;  // a plane through v on that side
                Planes planes = planes_;
                slot(planes, d) = P;
                if (!changes(planes)) {
                    ++tally_.unchanged;
                    continue;
                }
                if (std::abs(j) >= s_.options.reach - 1) ++tally_.hits_at_reach;
                hits[d].push_back(P);
            }
        combine(hits);
    }

private:
    static std::optional<std::int64_t>& slot(Planes& p, std::size_t d) { return d % 2 ? p.hi[d / 2] : p.lo[d / 2]; }

    // Per axis and side none or one of its hits; at least one, at most max_planes.
    void combine(const std::array<std::vector<std::int64_t>, 6>& hits) {
        std::array<std::size_t, 6> at{};  // 0: none, else index + 1
        for (bool more = true; more;) {
            Planes planes = planes_;
            for (std::size_t d = 0; d < 6; ++d)
                if (at[d] > 0) slot(planes, d) = hits[d][at[d] - 1];
            const int n = planes.count() - planes_.count();
            if (n > 0 && n <= s_.options.max_planes) {
                ++tally_.combinations[static_cast<std::size_t>(planes_.count())];
                check(planes);
            }
            more = false;
            for (std::size_t d = 0; d < 6 && !more; ++d) {
                if (++at[d] <= hits[d].size()) more = true;
                else at[d] = 0;
            }
        }
    }

    // The pair under `planes`; `hit` set if a cell they put outside, and the base does not,
    // is asked about (Lemma S5: else the run is the base run).
    Pair split_under(const Planes& planes, bool& hit) const {
        StatusModel model;
        model.outside = [&](const Status& x) {
            if (!planes.outside(x, s_.inf.unit)) return false;
            if (!planes_.outside(x, s_.inf.unit)) hit = true;
            return true;
        };
        Forcing forced(inside_, model.outside);
        return split(s_.inf, s_.index, v_, g_, inside_, forced, model);
    }

    bool changes(const Planes& planes) const {
        bool hit = false;
        (void)split_under(planes, hit);
        return hit;
    }

    void fail(const Planes& planes, const std::string& why) {
        ++tally_.failed;
        ++s_.failed;
        if (tally_.failures.size() >= 10) return;
        std::ostringstream os;
        os << "v-g=" << v_ - g_ << " g=" << g_ << " planes" << planes.describe() << " levels";
        for (int l : levels_) os << ' ' << l;
        os << ": " << why;
        tally_.failures.push_back(os.str());
    }

    // Every star under `planes`, checked (W11 for a corner pair whose search gives up).
    void check(const Planes& planes) {
        bool hit = false;
        const Pair p = split_under(planes, hit);
        Stars stars;
        try {
            stars = stars_by_search(s_.cubes, p, tally_.search_nodes, s_.options.search_limit);
        } catch (const SearchTooLarge& e) {
            if (planes_.count() == 0 && is_corner_pair(s_.inf, p, v_)) return check_corner(planes, p);
            return fail(planes, e.what());
        }
        for (const auto& [pieces, contexts] : stars) {
            if (std::all_of(pieces.begin(), pieces.end(), [](int x) { return x == -1; })) {
                ++tally_.empty;
                continue;
            }
            ++tally_.stars;
            if (const auto why = star_defect(p, contexts, planes, pieces)) fail(planes, *why);
            else ++tally_.passed;
        }
    }

    // B1-B5 if a plane passes through v, else W9 (vi)'s interior checks; a star that passes
    // is told (options.passed).
    std::optional<std::string> star_defect(const Pair& p, const std::vector<int>& contexts, const Planes& planes,
                                           const std::vector<int>& pieces) {
        try {
            const ConfigurationComplex star = build_star(s_.inf, s_.rule, cache_, p, v_, contexts);
            std::optional<std::string> why;
            if (planes_.count() > 0) why = boundary_vertex_defect(star.complex, sides_);
            else if (const ConfigurationReport r = detail::analyse(star, at_v, away_from_v); !r.ok() || r.checked_vertices != 1)
                why = r.summary();
            if (!why && s_.options.passed) s_.options.passed(label(planes, pieces), star.complex);
            return why;
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
    }

    // The further planes are those of `planes` not through v.
    WeakNearRootStarLabel label(const Planes& planes, const std::vector<int>& pieces) const {
        WeakNearRootStarLabel out{parity(), v_ - g_, levels_, sides_, {}, {}, pieces};
        for (std::size_t a = 0; a < 3; ++a) {
            if (planes.lo[a] != planes_.lo[a]) out.below[a] = planes.lo[a];
            if (planes.hi[a] != planes_.hi[a]) out.above[a] = planes.hi[a];
        }
        return out;
    }
    int parity() const {
        const std::int64_t E = cell_size(s_.inf.unit, 0);
        int t = 0;
        for (int a = 0; a < 3; ++a) t |= (g_[a] / E != 0 ? 1 : 0) << a;
        return t;
    }

    void check_corner(const Planes& planes, const Pair& p) {
        try {
            const CornerCheck c = check_corner_pair(s_.inf, s_.rule, cache_, s_.cubes, p, v_, s_.options.search_limit);
            tally_.search_nodes += c.search_nodes;
            if (c.passed) ++tally_.corner_pairs;
            else fail(planes, "corner pair (W11): " + c.defect);
        } catch (const std::exception& e) {
            fail(planes, std::string("corner pair (W11): ") + e.what());
        }
    }

    Shared& s_;
    WeakNearRootStarCheck& tally_;
    detail::TemplateCache& cache_;
    const LatticePoint v_, g_;
    const std::array<int, 8> levels_;
    const RootSides sides_;
    Planes planes_;  // the planes through v
    std::vector<weak_stars::Leaf> inside_;
};

// Every choice of planes through v (the axes where g and v are on a level-(m-1) plane,
// a side each; the configuration symmetric across them), the empty choice included.
template <class Visit>
void each_base(const LatticePoint& v, const std::array<int, 3>& parity, const std::array<int, 8>& levels, Visit&& visit) {
    unsigned axes = 0;
    for (int a = 0; a < 3; ++a)
        if (v[a] == 0 && parity[static_cast<std::size_t>(a)] == 0) axes |= 1U << a;
    for (unsigned through = 0; through < 8; ++through) {
        if ((through & ~axes) || !symmetric(levels, through)) continue;
        for (unsigned minus = 0; minus < 8; ++minus) {
            if (minus & ~through) continue;
            RootSides sides{};
            for (std::size_t a = 0; a < 3; ++a)
                if ((through >> a) & 1U) sides[a] = (minus >> a) & 1U ? -1 : 1;
            visit(sides);
        }
    }
}

void add(WeakNearRootStarCheck& to, WeakNearRootStarCheck& from) {
    for (std::size_t k = 0; k < 4; ++k) to.combinations[k] += from.combinations[k];
    to.unchanged += from.unchanged;
    to.stars += from.stars;
    to.empty += from.empty;
    to.passed += from.passed;
    to.failed += from.failed;
    to.search_nodes += from.search_nodes;
    to.corner_pairs += from.corner_pairs;
    to.hits_at_reach += from.hits_at_reach;
    for (auto& f : from.failures)
        if (to.failures.size() < 10) to.failures.push_back(std::move(f));
}

}  // namespace

WeakNearRootStarCheck run_weak_near_root_stars(const TransitionRule& rule, const ElementLibrary& library,
                                               const WeakStarInfluence& inf, const WeakNearRootStarOptions& options) {
    WeakNearRootStarCheck result;
    result.rule = rule.name();
    Shared shared{rule, inf, options, {}, piece_cubes(inf)};
    for (std::size_t q = 0; q < inf.positions.size(); ++q) shared.index[inf.positions[q].position] = q;
    const std::int64_t E = cell_size(inf.unit, 0);
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    std::mutex tally;
    for (int t = 0; t < 8; ++t) {
        if (!((options.parities >> t) & 1U)) continue;
        const std::array<int, 3> parity{t & 1, (t >> 1) & 1, (t >> 2) & 1};
        const LatticePoint g = LatticePoint{parity[0], parity[1], parity[2]} * E;
        const std::set<LatticePoint> found = candidates(inf, g, E / 2);
        const std::vector<LatticePoint> vertices(found.begin(), found.end());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size()), [&](const auto& range) {
            WeakNearRootStarCheck local;
            auto& cache = caches.local();
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                if (options.stop_after > 0 && shared.failed.load() >= options.stop_after) break;
                const LatticePoint& v = vertices[i];
                Configurations(v, inf.unit).each([&](const std::array<int, 8>& levels, const std::array<weak_stars::Leaf, 8>& leaves) {
                    each_base(v, parity, levels, [&](const RootSides& sides) { Base(shared, local, cache, v, g, levels, leaves, sides).run(); });
                });
            }
            const std::lock_guard lock(tally);
            add(result, local);
        });
    }
    return result;
}

}  // namespace dualhex
