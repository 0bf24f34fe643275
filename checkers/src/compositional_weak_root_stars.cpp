// The weak stars of vertices on the root surface (compositional_weak_root_stars.hpp,
// run_weak_root_stars; proofs/README.md W13): W9's enumeration with the root planes through
// v, the inside leaves' stars checked with B1-B5.
#include "dualhex/checkers/compositional_weak_root_stars.hpp"

#include <atomic>
#include <bit>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "weak_star_pair.hpp"

namespace dualhex {
namespace {

using namespace weak_stars;

struct Type {
    RootSides sides{};
    std::array<int, 3> parity{};
    int k = 0;
};

// Every set S of root axes with a side per axis and a parity of g that is 0 on S (g_a = v_a
// lies on a root plane, a level-(m-1) plane: even in level-m units).
std::vector<Type> types(unsigned planes) {
    std::vector<Type> out;
    for (unsigned axes = 1; axes < 8; ++axes) {
        const int k = std::popcount(axes);
        if (!((planes >> (k - 1)) & 1U)) continue;
        for (unsigned minus = 0; minus < 8; ++minus) {
            if (minus & ~axes) continue;
            for (unsigned t = 0; t < 8; ++t) {
                if (t & axes) continue;
                Type type;
                type.k = k;
                for (int a = 0; a < 3; ++a) {
                    type.sides[static_cast<std::size_t>(a)] = (axes >> a) & 1U ? ((minus >> a) & 1U ? -1 : 1) : 0;
                    type.parity[static_cast<std::size_t>(a)] = static_cast<int>((t >> a) & 1U);
                }
                out.push_back(type);
            }
        }
    }
    return out;
}

// A cell (or a leaf's cell) beyond a root plane of `sides` (the planes are x_a = 0: cell
// index c_a covers [c_a, c_a + 1] cells, so the inside of side +1 is c_a >= 0).
bool outside(const RootSides& sides, const Index3& c) {
    for (std::size_t a = 0; a < 3; ++a)
        if ((sides[a] > 0 && c[a] < 0) || (sides[a] < 0 && c[a] >= 0)) return true;
    return false;
}

// Sign octant s (bit a set: +) lies on the root side of every plane.
bool inside_octant(const RootSides& sides, int s) {
    for (int a = 0; a < 3; ++a) {
        const int side = sides[static_cast<std::size_t>(a)];
        if (side != 0 && (((s >> a) & 1) != 0) != (side > 0)) return false;
    }
    return true;
}

// The smallest of x and its images under the reflections across the root planes (a level's
// cell c_a -> -1 - c_a: the planes are on every level's lattice from m - 1 down).
Status mirror_representative(const RootSides& sides, const Status& x) {
    Status best = x;
    for (unsigned flip = 1; flip < 8; ++flip) {
        Status y = x;
        bool ok = true;
        for (std::size_t a = 0; a < 3; ++a) {
            if (!((flip >> a) & 1U)) continue;
            ok = ok && sides[a] != 0;
            y.second[a] = -1 - y.second[a];
        }
        if (ok) best = std::min(best, y);
    }
    return best;
}

// The mirrored grid's configuration is its own image under each reflection.
bool symmetric(const std::array<int, 8>& levels, const RootSides& sides) {
    for (int a = 0; a < 3; ++a)
        if (sides[static_cast<std::size_t>(a)] != 0)
            for (int s = 0; s < 8; ++s)
                if (levels[static_cast<std::size_t>(s)] != levels[static_cast<std::size_t>(s ^ (1 << a))]) return false;
    return true;
}

std::string describe(const Type& type, const Pair& p, const std::vector<int>& contexts, const std::string& why) {
    std::ostringstream os;
    os << "sides=(" << type.sides[0] << ',' << type.sides[1] << ',' << type.sides[2] << ") g=(" << type.parity[0] << ','
       << type.parity[1] << ',' << type.parity[2] << ") v-g=" << p.v << " leaves";
    for (std::size_t n = 0; n < p.leaves.size(); ++n) {
        const auto& l = p.leaves[n].at.leaf;
        os << " [m+" << l.level << " (" << l.cell[0] << ',' << l.cell[1] << ',' << l.cell[2] << ") ctx "
           << (n < contexts.size() ? contexts[n] : -1) << ']';
    }
    os << ": " << why;
    return os.str();
}

// What the run shares across threads.
struct Run {
    const TransitionRule& rule;
    const WeakStarInfluence& inf;
    const WeakRootStarOptions& options;
    const bool mirror, any_outside;
    std::map<LatticePoint, std::size_t> index;
    PieceCubes cubes;
    std::atomic<long> failed{0};

    // The inside leaves' pair under the policy's model (W13 (b), (c)).
    Pair pair_of(const Type& type, const LatticePoint& v, const LatticePoint& g, const std::array<weak_stars::Leaf, 8>& leaves) const {
        std::vector<weak_stars::Leaf> inside;
        for (int s = 0; s < 8; ++s)
            if (inside_octant(type.sides, s)) inside.push_back(leaves[static_cast<std::size_t>(s)]);
        const RootSides sides = type.sides;
        StatusModel model;
        std::optional<Forcing> forced;
        if (mirror) {  // Ĝ: its 8 leaves force; a status is one with its mirror images
            model.canonical = [sides](const Status& x) { return mirror_representative(sides, x); };
            forced.emplace(leaves);
        } else {  // G: the inside leaves force; outside cells are not fine (Coarse) or free (any
                  // function of the cell), and nothing implies into or out of them
            model.outside = [sides](const Status& x) { return outside(sides, x.second); };
            forced.emplace(inside, model.outside, any_outside);
            if (options.outside_fine_for)
                model.read = [this, sides](const Status& x, const weak_stars::Leaf& reader) -> std::optional<bool> {
                    if (!outside(sides, x.second)) return std::nullopt;
                    return options.outside_fine_for(reader.level, reader.cell);
                };
        }
        return split(inf, index, v, g, inside, *forced, model);
    }

    // Every star of the pair, B1-B5 at v (a search that gives up is a failure, never a pass).
    void check(const Type& type, const LatticePoint& v, const LatticePoint& g, const std::array<int, 8>& levels, const Pair& p,
               WeakRootStarCheck& local, detail::TemplateCache& cache) {
        const std::size_t k = static_cast<std::size_t>(type.k - 1);
        const auto fail = [&](const std::vector<int>& contexts, const std::string& why) {
            ++local.failed[k];
            ++failed;
            if (local.failures.size() < 10) local.failures.push_back(describe(type, p, contexts, why));
        };
        Stars stars;
        try {
            stars = stars_by_search(cubes, p, local.search_nodes, options.search_limit);
        } catch (const SearchTooLarge& e) {
            return fail({}, e.what());
        }
        for (const auto& [pieces, contexts] : stars) {
            const auto tell = [&](const CellComplex* complex) {
                if (!options.stars) return;
                WeakRootStar star{type.sides, type.parity, v - g, levels, {}, pieces, complex};
                for (int s = 0; s < 8; ++s)
                    if (!mirror && !inside_octant(type.sides, s)) star.levels[static_cast<std::size_t>(s)] = -1;
                for (const LeafBits& b : p.leaves) star.leaves.push_back({b.at.leaf.level, b.at.leaf.cell});
                options.stars(star);
            };
            if (std::all_of(pieces.begin(), pieces.end(), [](int x) { return x == -1; })) {
                ++local.empty[k];
                tell(nullptr);
                continue;
            }
            ++local.stars[k];
            try {
                const ConfigurationComplex star = build_star(inf, rule, cache, p, v, contexts);
                tell(&star.complex);
                if (const auto why = boundary_vertex_defect(star.complex, type.sides)) fail(contexts, *why);
                else ++local.passed[k];
            } catch (const std::exception& e) {  // the rule refused or threw
                fail(contexts, e.what());
            }
        }
    }
};

void add(WeakRootStarCheck& to, WeakRootStarCheck& from) {
    for (std::size_t k = 0; k < 3; ++k) {
        to.pairs[k] += from.pairs[k];
        to.stars[k] += from.stars[k];
        to.empty[k] += from.empty[k];
        to.passed[k] += from.passed[k];
        to.failed[k] += from.failed[k];
    }
    to.search_nodes += from.search_nodes;
    to.max_free = std::max(to.max_free, from.max_free);
    for (auto& f : from.failures)
        if (to.failures.size() < 10) to.failures.push_back(std::move(f));
}

}  // namespace

WeakRootStarCheck run_weak_root_stars(const TransitionRule& rule, const ElementLibrary& library, const WeakStarInfluence& inf,
                                      BoundaryPolicy policy, const WeakRootStarOptions& options) {
    WeakRootStarCheck result;
    result.rule = rule.name();
    result.policy = to_string(policy);
    if (policy == BoundaryPolicy::AnyOutside && options.outside_fine_for)
        throw std::invalid_argument("run_weak_root_stars: outside_fine_for is a variant of Coarse");
    Run run{rule, inf, options, policy == BoundaryPolicy::Mirror, policy == BoundaryPolicy::AnyOutside, {}, piece_cubes(inf)};
    for (std::size_t q = 0; q < inf.positions.size(); ++q) run.index[inf.positions[q].position] = q;
    const std::int64_t E = cell_size(inf.unit, 0);
    const std::vector<Type> all_types = types(options.planes);
    std::vector<std::pair<std::size_t, LatticePoint>> jobs;  // (type, v)
    for (std::size_t i = 0; i < all_types.size(); ++i) {
        const Type& type = all_types[i];
        ++result.types[static_cast<std::size_t>(type.k - 1)];
        const LatticePoint g = LatticePoint{type.parity[0], type.parity[1], type.parity[2]} * E;
        for (const LatticePoint& v : candidates(inf, g, E / 2)) {
            bool on_planes = true;  // v on every root plane of the type (g_a = 0 there)
            for (int a = 0; a < 3; ++a) on_planes = on_planes && (type.sides[static_cast<std::size_t>(a)] == 0 || v[a] == 0);
            if (on_planes) jobs.push_back({i, v});
        }
    }
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    std::mutex tally;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, jobs.size()), [&](const auto& range) {
        WeakRootStarCheck local;
        auto& cache = caches.local();
        for (std::size_t j = range.begin(); j != range.end(); ++j) {
            if (options.stop_after > 0 && run.failed.load() >= options.stop_after) break;
            const Type& type = all_types[jobs[j].first];
            const LatticePoint& v = jobs[j].second;
            const LatticePoint g = LatticePoint{type.parity[0], type.parity[1], type.parity[2]} * E;
            Configurations(v, inf.unit).each([&](const std::array<int, 8>& levels, const std::array<weak_stars::Leaf, 8>& leaves) {
                // Mirror: Ĝ's configurations are symmetric. Coarse: the outside octants hold no
                // leaves, and the inside configurations are the inside halves of the symmetric
                // ones (W13 (c)).
                if (!symmetric(levels, type.sides)) return;
                ++local.pairs[static_cast<std::size_t>(type.k - 1)];
                const Pair p = run.pair_of(type, v, g, leaves);
                int free = p.n_shared;
                for (const LeafBits& b : p.leaves) free += b.n_own;
                local.max_free = std::max(local.max_free, free);
                run.check(type, v, g, levels, p, local, cache);
            });
        }
        const std::lock_guard lock(tally);
        add(result, local);
    });
    return result;
}

}  // namespace dualhex
