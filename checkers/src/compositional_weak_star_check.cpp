// The star enumeration of W7 (compositional_weak_stars.hpp, run_weak_stars): per vertex v
// near g and configuration of the leaves at v, every distinct tuple of the leaves' pieces
// over the free statuses their relevant bits read (shared ones jointly, each leaf's private
// ones per leaf), each tuple built as the leaves' elements and checked at v.
#include <atomic>
#include <cmath>
#include <mutex>
#include <optional>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "weak_star_pair.hpp"
#include "window_check.hpp"

namespace dualhex::weak_stars {
namespace {

bool holds(const std::vector<std::pair<int, int>>& implies, const auto& value) {
    return std::all_of(implies.begin(), implies.end(), [&](const auto& i) { return !value(i.first) || value(i.second); });
}

// The cells of t (placed at origin + scale * p) that have v as a vertex, translated so that
// v is the origin.
void emit_cells_at(ComplexBuilder& builder, const detail::ElementTemplate& t, const LatticePoint& origin, std::int64_t scale,
                   const LatticePoint& v) {
    std::vector<VertexHandle> loop;
    std::vector<HalfFaceHandle> halffaces;
    const auto world = [&](std::uint32_t n) { return origin + t.points[n] * scale - v; };
    for (std::size_t c = 0; c < t.n_cells(); ++c) {
        bool at_v = false;
        for (std::uint32_t q = t.face_offsets[t.cell_offsets[c]]; q < t.face_offsets[t.cell_offsets[c + 1]] && !at_v; ++q)
            at_v = world(t.face_points[q]) == LatticePoint{};
        if (!at_v) continue;
        halffaces.clear();
        for (std::uint32_t f = t.cell_offsets[c]; f < t.cell_offsets[c + 1]; ++f) {
            loop.clear();
            for (std::uint32_t q = t.face_offsets[f]; q < t.face_offsets[f + 1]; ++q) loop.push_back(builder.add_vertex(world(t.face_points[q])));
            halffaces.push_back(builder.add_face(loop));
        }
        builder.add_cell(halffaces);
    }
}

}  // namespace

ConfigurationComplex build_star(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                                const Pair& p, const LatticePoint& v_world, const std::vector<int>& contexts) {
    ConfigurationComplex out;
    out.unit = inf.unit;
    ComplexBuilder builder;
    for (std::size_t n = 0; n < p.leaves.size(); ++n) {
        const LeafBits& b = p.leaves[n];
        const std::int64_t S = cell_size(inf.unit, b.at.leaf.level);
        const LatticePoint corner = LatticePoint{b.at.leaf.cell[0], b.at.leaf.cell[1], b.at.leaf.cell[2]} * S;
        if (b.at.leaf.level == kFinest) {
            emit_cells_at(builder, cache.hex(S), corner, 1, v_world);
            continue;
        }
        const LeafContext ctx = set_visible_context(b.at.frame, contexts[n], inf.octant_bits);
        const std::optional<Placement> placement = rule.place(ctx);
        if (!placement) {
            emit_cells_at(builder, cache.hex(S), corner, 1, v_world);
            continue;
        }
        detail::check_placement_symmetry(*placement);
        const auto& t = cache.placed(cache.element_index(placement->element), world_symmetry(ctx, *placement));
        emit_cells_at(builder, t, ctx.application_point * S, S / inf.unit, v_world);
    }
    out.complex = std::move(builder).build();
    return out;
}

Pair split(const WeakStarInfluence& inf, const std::map<LatticePoint, std::size_t>& index, const LatticePoint& v,
           const LatticePoint& g, const std::array<Leaf, 8>& leaves) {
    Forcing forced(leaves);
    return split(inf, index, v, g, std::vector<Leaf>(leaves.begin(), leaves.end()), forced, StatusModel{});
}

Pair split(const WeakStarInfluence& inf, const std::map<LatticePoint, std::size_t>& index, const LatticePoint& v,
           const LatticePoint& g, const std::vector<Leaf>& leaves, Forcing& forced, const StatusModel& model) {
    Pair p{v - g};
    std::set<std::pair<int, Index3>> distinct;
    std::map<Status, std::set<int>> readers;
    const auto value = [&](const Status& x, const Leaf& reader) -> std::optional<bool> {
        if (model.read)
            if (const auto r = model.read(x, reader)) return r;
        return forced(x);
    };
    for (const Leaf& leaf : leaves) {
        if (!distinct.insert({leaf.level, leaf.cell}).second) continue;
        LeafBits b{leaf_at(inf, index, v, leaf)};
        if (leaf.level == kFinest) {
            const std::int64_t S = cell_size(inf.unit, kFinest);
            b.hex_corner = true;
            for (int a = 0; a < 3; ++a) b.hex_corner = b.hex_corner && v[a] % S == 0;
        }
        std::set<Status> mine;
        for (const auto& [bit, x] : b.at.reads)
            if (!value(x, leaf)) mine.insert(model.name(x));
        for (const Status& x : mine) readers[x].insert(static_cast<int>(p.leaves.size()));
        p.leaves.push_back(std::move(b));
    }
    // shared: read by two leaves, or tied by an implication to a status another leaf reads
    std::set<Status> shared;
    for (const auto& [x, who] : readers)
        if (who.size() > 1) shared.insert(x);
    const auto links = implications(readers, model);
    for (const auto& [a, b] : links)
        if (readers.at(a) != readers.at(b)) shared.insert(a), shared.insert(b);
    std::map<Status, int> shared_index;
    for (const Status& x : shared) shared_index.emplace(x, static_cast<int>(shared_index.size()));
    p.n_shared = static_cast<int>(shared_index.size());
    for (std::size_t n = 0; n < p.leaves.size(); ++n) {
        LeafBits& b = p.leaves[n];
        std::map<Status, int> own_index;
        for (const auto& [bit, raw] : b.at.reads) {
            const Status x = model.name(raw);
            if (const auto f = value(raw, b.at.leaf)) b.fixed |= *f ? 1 << bit : 0;
            else if (const auto it = shared_index.find(x); it != shared_index.end()) b.shared.push_back({bit, it->second});
            else b.own.push_back({bit, own_index.emplace(x, static_cast<int>(own_index.size())).first->second});
        }
        b.n_own = static_cast<int>(own_index.size());
        const auto code = [&](const Status& x) { return own_index.count(x) ? own_index.at(x) : -1 - shared_index.at(x); };
        for (const auto& [a, c] : links)
            if (own_index.count(a) || own_index.count(c)) b.implies.push_back({code(a), code(c)});
    }
    for (const auto& [a, c] : links)
        if (shared_index.count(a) && shared_index.count(c)) p.implies.push_back({shared_index.at(a), shared_index.at(c)});
    return p;
}

// Per shared assignment, each leaf's distinct pieces with a witness context; their products.
Stars stars_by_product(const WeakStarInfluence& inf, const Pair& p, long& assignments) {
    std::map<std::vector<int>, std::vector<int>> out;  // pieces per leaf -> contexts per leaf
    for (std::uint64_t sa = 0; sa < (std::uint64_t{1} << p.n_shared); ++sa) {
        if (!holds(p.implies, [sa](int i) { return ((sa >> i) & 1U) != 0; })) continue;
        ++assignments;
        std::vector<std::vector<std::pair<int, int>>> options;  // per leaf: (piece, context)
        for (const LeafBits& b : p.leaves) {
            auto& mine = options.emplace_back();
            if (b.at.position < 0) {
                mine.push_back({b.hex_corner ? 0 : -1, 0});
                continue;
            }
            int base = b.fixed;
            for (const auto& [bit, i] : b.shared) base |= ((sa >> i) & 1U) ? 1 << bit : 0;
            for (int pa = 0; pa < 1 << b.n_own; ++pa) {
                if (!holds(b.implies, [&](int c) { return c >= 0 ? ((pa >> c) & 1) != 0 : ((sa >> (-1 - c)) & 1U) != 0; })) continue;
                int ctx = base;
                for (const auto& [bit, i] : b.own) ctx |= ((pa >> i) & 1) ? 1 << bit : 0;
                const int piece = inf.piece[static_cast<std::size_t>(b.at.position)][static_cast<std::size_t>(ctx)];
                if (std::none_of(mine.begin(), mine.end(), [piece](const auto& o) { return o.first == piece; })) mine.push_back({piece, ctx});
            }
        }
        std::vector<std::size_t> at(options.size(), 0);
        for (bool more = true; more;) {
            std::vector<int> pieces, contexts;
            for (std::size_t n = 0; n < options.size(); ++n) {
                pieces.push_back(options[n][at[n]].first);
                contexts.push_back(options[n][at[n]].second);
            }
            out.emplace(std::move(pieces), std::move(contexts));
            more = false;
            for (std::size_t n = 0; n < options.size() && !more; ++n) {
                if (++at[n] < options[n].size()) more = true;
                else at[n] = 0;
            }
        }
    }
    return out;
}

}  // namespace dualhex::weak_stars

namespace dualhex {
namespace {

using namespace weak_stars;

std::string describe(const std::array<int, 3>& parity, const Pair& p, const std::vector<int>& contexts, const std::string& why) {
    std::ostringstream os;
    os << "g=(" << parity[0] << ',' << parity[1] << ',' << parity[2] << ") v-g=" << p.v << " leaves";
    for (std::size_t n = 0; n < p.leaves.size(); ++n) {
        const auto& l = p.leaves[n].at.leaf;
        os << " [m+" << l.level << " (" << l.cell[0] << ',' << l.cell[1] << ',' << l.cell[2] << ") ctx " << contexts[n]
           << " at " << p.leaves[n].at.position << ']';
    }
    os << ": " << why;
    return os.str();
}

// A corner pair: W11's pieces and quadrants (not with AlwaysByWitnesses), then W14 (f)'s
// witness stars, checked, when they are the check or options.corner_witness wants them
// (told with `pair`'s fields and the tuple's). The first reason it fails, or nothing.
std::optional<std::string> corner_defect(const WeakStarInfluence& inf, const TransitionRule& rule, detail::TemplateCache& cache,
                                         const PieceCubes& cubes, const Pair& p, const LatticePoint& v, const WeakStarOptions& options,
                                         const WeakCornerLabel& pair, WeakStarCheck& local) {
    const bool by_witnesses = options.corner_pairs == CornerPairs::AlwaysByWitnesses;
    try {
        if (!by_witnesses) {
            const CornerCheck c = check_corner_pair(inf, rule, cache, cubes, p, v, options.search_limit);
            local.search_nodes += c.search_nodes;
            local.corner_pieces += c.pieces;
            local.corner_quadrant_tuples += c.quadrant_tuples;
            if (!c.passed) return "W11: " + c.defect;
        }
        if (!by_witnesses && !options.corner_witness) return std::nullopt;
        std::optional<std::string> why;
        local.corner_witnesses += corner_witness_stars(
            inf, rule, cache, cubes, p, v, options.search_limit,
            [&](int o, int o2, const std::vector<int>& pieces, const ConfigurationComplex& star) {
                const ConfigurationReport r = detail::analyse(star, at_v, away_from_v);
                if (!r.ok() || r.checked_vertices != 1) why = "a witness star (W14 (f)): " + r.summary();
                else if (options.corner_witness) options.corner_witness({pair.parity, pair.v, pair.levels, o, o2, pieces}, star.complex);
            });
        return why;
    } catch (const std::exception& e) {  // a search gave up, or the rule threw
        return std::string(e.what());
    }
}

}  // namespace

WeakStarCheck run_weak_stars(const TransitionRule& rule, const ElementLibrary& library, const WeakStarInfluence& inf,
                             const WeakStarOptions& options) {
    const long stop_after = options.stop_after;
    WeakStarCheck result;
    result.rule = rule.name();
    std::map<LatticePoint, std::size_t> index;
    for (std::size_t q = 0; q < inf.positions.size(); ++q) index[inf.positions[q].position] = q;
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    std::mutex tally;
    std::atomic<long> failed{0};
    std::optional<PieceCubes> cubes;
    if (!options.count_only) cubes = piece_cubes(inf);
    for (int t = 0; t < 8; ++t) {
        if (!((options.parities >> t) & 1U)) continue;
        const std::array<int, 3> parity{t & 1, (t >> 1) & 1, (t >> 2) & 1};
        const LatticePoint g = LatticePoint{parity[0], parity[1], parity[2]} * cell_size(inf.unit, 0);
        std::vector<LatticePoint> vertices;
        for (const LatticePoint& v : candidates(inf, g, cell_size(inf.unit, 0) / 2))
            if (!options.vertex || options.vertex(v - g)) vertices.push_back(v);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size()), [&](const auto& range) {
            WeakStarCheck local;
            auto& cache = caches.local();
            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                if (stop_after > 0 && failed.load() >= stop_after) break;
                const LatticePoint& v = vertices[i];
                Configurations(v, inf.unit).each([&](const std::array<int, 8>& levels, const std::array<Leaf, 8>& leaves) {
                    ++local.pairs;
                    const Pair p = split(inf, index, v, g, leaves);
                    local.joint_bound += std::ldexp(1.0, p.n_shared);
                    local.max_shared = std::max(local.max_shared, p.n_shared);
                    if (options.count_only) return;
                    const long failed_before = local.failed;
                    const auto verdict = [&] {
                        if (options.verdicts) options.verdicts(v - g, levels, local.failed == failed_before);
                    };
                    const auto fail = [&](const std::vector<int>& contexts, const std::string& why) {
                        ++local.failed;
                        ++failed;
                        if (local.failures.size() < 10) local.failures.push_back(describe(parity, p, contexts, why));
                    };
                    const bool corner = options.corner_pairs != CornerPairs::Never && is_corner_pair(inf, p, v);
                    const auto by_corner = [&] {
                        const WeakCornerLabel pair{t, v - g, levels, 0, 0, {}};
                        if (const auto why = corner_defect(inf, rule, cache, *cubes, p, v, options, pair, local))
                            fail(std::vector<int>(p.leaves.size(), -1), "corner pair: " + *why);
                        else ++local.corner_pairs;
                        verdict();
                    };
                    const bool always = options.corner_pairs == CornerPairs::Always || options.corner_pairs == CornerPairs::AlwaysByWitnesses;
                    if (corner && always) return by_corner();
                    Stars stars;
                    try {
                        stars = options.reference_product ? stars_by_product(inf, p, local.assignments)
                                                          : stars_by_search(*cubes, p, local.search_nodes, options.search_limit);
                    } catch (const SearchTooLarge& e) {
                        if (corner) return by_corner();
                        fail(std::vector<int>(p.leaves.size(), -1), e.what());
                        return verdict();
                    }
                    for (const auto& [pieces, contexts] : stars) {
                        if (options.stars) options.stars(v - g, pieces);
                        if (std::all_of(pieces.begin(), pieces.end(), [](int x) { return x == -1; })) {
                            ++local.empty;
                            continue;
                        }
                        ++local.stars;
                        if (!options.build_stars) continue;
                        std::optional<ConfigurationComplex> star;
                        const auto build = [&] { return *(star = build_star(inf, rule, cache, p, v, contexts)); };
                        const ConfigurationReport r = detail::check(0, build, at_v, away_from_v);
                        if (!r.ok() || r.checked_vertices != 1) {
                            fail(contexts, r.summary());
                            continue;
                        }
                        ++local.passed;
                        if (options.passed) options.passed({t, v - g, levels, pieces}, star->complex);
                    }
                    verdict();
                });
            }
            const std::lock_guard lock(tally);
            result.pairs += local.pairs;
            result.assignments += local.assignments;
            result.search_nodes += local.search_nodes;
            result.corner_pairs += local.corner_pairs;
            result.corner_pieces += local.corner_pieces;
            result.corner_quadrant_tuples += local.corner_quadrant_tuples;
            result.corner_witnesses += local.corner_witnesses;
            result.stars += local.stars;
            result.empty += local.empty;
            result.joint_bound += local.joint_bound;
            result.max_shared = std::max(result.max_shared, local.max_shared);
            result.passed += local.passed;
            result.failed += local.failed;
            for (auto& f : local.failures)
                if (result.failures.size() < 10) result.failures.push_back(std::move(f));
        });
    }
    return result;
}

}  // namespace dualhex
