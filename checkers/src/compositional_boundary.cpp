// The root-boundary enumeration (compositional_boundary.hpp): the 56 boundary types, their
// distinct half windows (inside leaves of B(g), outside octant cubes fixed by the policy),
// each built and checked at every vertex on its root planes.
#include "dualhex/checkers/compositional_boundary.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <sstream>
#include <stdexcept>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "compositional_products.hpp"
#include "compositional_windows.hpp"
#include "configuration_parts.hpp"
#include "class_check.hpp"
#include "oriented_form.hpp"
#include "window_classes.hpp"
#include "dualhex/install/element_templates.hpp"

namespace dualhex {
namespace {

using detail::Index3;
using compositional_detail::local_of_bit;
using compositional_detail::reach_bits;

bool inside(const Index3& o, const RootSides& s) {
    for (std::size_t a = 0; a < 3; ++a)
        if ((s[a] > 0 && o[a] < 0) || (s[a] < 0 && o[a] >= 0)) return false;
    return true;
}

// One boundary type: g, the root sides, the inside leaves and the inside octant cubes they
// depend on (through the policy for the outside ones they read).
struct BoundaryType {
    std::array<int, 3> parity{};
    RootSides sides{};
    std::vector<LatticePoint> leaves;
    std::vector<Index3> vars;
    std::vector<std::vector<int>> depends;  // per leaf: indices into vars, sorted
    std::vector<int> own;                   // per leaf: its own octant's index
    compositional_detail::OctantIndex var_of;  // vars' indices by octant
};

struct Status {  // the status function a pattern (bit i: vars[i] fine) gives the rule
    const BoundaryType& t;
    const OutsidePolicy& policy;
    std::uint64_t pattern;
    bool var(const Index3& o) const {
        const int i = t.var_of(o);
        return i >= 0 && ((pattern >> i) & 1U);  // unread: cannot matter
    }
    const LatticePoint& reader;
    bool operator()(const Index3& o) const {
        if (inside(o, t.sides)) return var(o);
        const OutsideOctant out = policy(o, t.sides, reader);
        if (out.kind == OutsideOctant::Kind::Copy) return var(out.copy_of);
        if (out.kind == OutsideOctant::Kind::Free) return var(o);
        return out.kind == OutsideOctant::Kind::Fine;
    }
};

Index3 octant_of(const LatticePoint& leaf) {
    return {detail::floor_div(leaf.x, 2), detail::floor_div(leaf.y, 2), detail::floor_div(leaf.z, 2)};
}

BoundaryType boundary_type(const std::array<int, 3>& parity, const RootSides& sides, const TransitionRule& rule,
                           const OutsidePolicy& policy) {
    BoundaryType t{parity, sides, {}, {}, {}, {}, {}};
    const auto intern = [&](const Index3& o, bool free_outside) {
        if (!free_outside && !inside(o, sides)) throw std::logic_error("root policy: an outside cube copies an outside cube");
        const auto it = std::find(t.vars.begin(), t.vars.end(), o);
        if (it != t.vars.end()) return static_cast<int>(it - t.vars.begin());
        t.vars.push_back(o);
        return static_cast<int>(t.vars.size() - 1);
    };
    for (int n = 0; n < 8; ++n) {
        const LatticePoint leaf{parity[0] - 1 + (n & 1), parity[1] - 1 + ((n >> 1) & 1), parity[2] - 1 + ((n >> 2) & 1)};
        bool in = true;  // leaf [l, l+1] on a root axis: l = 0 (side +1) or l = -1 (side -1)
        for (int a = 0; a < 3; ++a)
            if (sides[static_cast<std::size_t>(a)] != 0) in = in && leaf[a] == (sides[static_cast<std::size_t>(a)] > 0 ? 0 : -1);
        if (!in) continue;
        const LeafContext frame = detail::coarse_leaf_context(leaf, [](const Index3&) { return false; });
        std::vector<int> mine{intern(octant_of(leaf), false)};
        t.own.push_back(mine.front());
        for (int b : reach_bits(rule)) {
            const Index3 o = detail::world_octant(frame, local_of_bit(b));
            if (inside(o, sides)) {
                mine.push_back(intern(o, false));
                continue;
            }
            const OutsideOctant out = policy(o, sides, leaf);
            if (out.kind == OutsideOctant::Kind::Copy) mine.push_back(intern(out.copy_of, false));
            if (out.kind == OutsideOctant::Kind::Free) mine.push_back(intern(o, true));
        }
        std::sort(mine.begin(), mine.end());
        mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
        t.leaves.push_back(leaf);
        t.depends.push_back(std::move(mine));
    }
    if (t.vars.size() > 63) throw std::length_error("root boundary: more than 63 octants read by one window");
    t.var_of = compositional_detail::OctantIndex(t.vars);
    return t;
}

// A leaf's outcome ("fine", "hex", "E/<symmetry>", "error: ...") for a pattern.
std::string outcome(const BoundaryType& t, std::size_t n, std::uint64_t pattern, const TransitionRule& rule,
                    const OutsidePolicy& policy) {
    if ((pattern >> t.own[n]) & 1U) return "fine";
    try {
        const auto p = rule.place(detail::coarse_leaf_context(t.leaves[n], Status{t, policy, pattern, t.leaves[n]}));
        return p ? p->element + "/" + std::to_string(p->symmetry.index()) : "hex";
    } catch (const std::exception& e) {
        return std::string("error: ") + e.what();
    }
}

// Every distinct window (distinct outcomes of the inside leaves), one witness pattern each
// (compositional_products.hpp): each leaf's outcome tabulated over the cubes it depends on.
std::vector<std::uint64_t> distinct_windows(const BoundaryType& t, const TransitionRule& rule, const OutsidePolicy& policy) {
    std::map<std::string, int> ids;
    std::vector<compositional_detail::LeafOutcomes> leaves(t.leaves.size());
    for (std::size_t n = 0; n < t.leaves.size(); ++n) {
        leaves[n].depends = t.depends[n];
        leaves[n].table.resize(std::size_t{1} << t.depends[n].size());
        for (std::uint64_t a = 0; a < leaves[n].table.size(); ++a) {
            std::uint64_t pattern = 0;
            for (std::size_t j = 0; j < t.depends[n].size(); ++j)
                if ((a >> j) & 1U) pattern |= std::uint64_t{1} << t.depends[n][j];
            const std::string o = outcome(t, n, pattern, rule, policy);
            leaves[n].table[a] = ids.emplace(o, static_cast<int>(ids.size())).first->second;
        }
    }
    int shared = 0;
    return compositional_detail::distinct_outcome_tuples(leaves, t.vars.size(), shared);
}

// The inside leaves of B(g) for one pattern, translated so that g is the origin, as the
// builder's parts (configuration_parts.hpp: a member proved an image needs no more).
ComplexBuilder::Parts half_window_parts(const BoundaryType& t, std::uint64_t pattern, const TransitionRule& rule,
                                        const OutsidePolicy& policy, detail::TemplateCache& cache) {
    const std::int64_t U = cache.unit();
    const LatticePoint g{t.parity[0], t.parity[1], t.parity[2]};
    const auto shift = [&](const LatticePoint& p) { return p - g * U; };
    ComplexBuilder builder;
    std::vector<VertexHandle> vs, loop;
    std::vector<HalfFaceHandle> hfs;
    for (std::size_t n = 0; n < t.leaves.size(); ++n) {
        const LatticePoint& leaf = t.leaves[n];
        if ((pattern >> t.own[n]) & 1U) {
            for (int c = 0; c < 8; ++c)
                detail::emit(builder, cache.hex(U / 2), leaf * U + LatticePoint{c & 1, (c >> 1) & 1, (c >> 2) & 1} * (U / 2),
                             1, shift, vs, loop, hfs);
            continue;
        }
        const LeafContext ctx = detail::coarse_leaf_context(leaf, Status{t, policy, pattern, leaf});
        (void)detail::emit_rule_leaf(builder, cache, rule, ctx, ctx.application_point * U, leaf * U, U, shift, vs, loop, hfs);
    }
    return std::move(builder).take_parts();
}

CellComplex build_half_window(const BoundaryType& t, std::uint64_t pattern, const TransitionRule& rule,
                              const OutsidePolicy& policy, detail::TemplateCache& cache) {
    return detail::complex_of(half_window_parts(t, pattern, rule, policy, cache));
}

std::string describe(const BoundaryType& t, std::uint64_t pattern) {
    std::ostringstream os;
    os << "g=(" << t.parity[0] << ',' << t.parity[1] << ',' << t.parity[2] << ") sides (" << t.sides[0] << ','
       << t.sides[1] << ',' << t.sides[2] << ") fine inside {";
    const char* sep = "";
    for (std::size_t i = 0; i < t.vars.size(); ++i)
        if ((pattern >> i) & 1U) {
            os << sep << '(' << t.vars[i][0] << ',' << t.vars[i][1] << ',' << t.vars[i][2] << ')';
            sep = " ";
        }
    os << '}';
    return os.str();
}

// The 56 types: every nonempty set of root axes, a side for each, g's other coordinates.
std::vector<std::pair<std::array<int, 3>, RootSides>> boundary_types() {
    std::vector<std::pair<std::array<int, 3>, RootSides>> out;
    for (unsigned axes = 1; axes < 8; ++axes)
        for (unsigned side_bits = 0; side_bits < 8; ++side_bits) {
            if (side_bits & ~axes) continue;
            for (unsigned odd = 0; odd < 8; ++odd) {
                if (odd & axes) continue;
                std::array<int, 3> parity{};
                RootSides sides{};
                for (unsigned a = 0; a < 3; ++a) {
                    parity[a] = static_cast<int>((odd >> a) & 1U);
                    if ((axes >> a) & 1U) sides[a] = ((side_bits >> a) & 1U) ? -1 : 1;
                }
                out.emplace_back(parity, sides);
            }
        }
    return out;
}

struct Outcome {
    bool ok = false;
    std::size_t checked = 0;
    std::array<std::size_t, 3> per_kind{};
    std::string why;
};

// The full check of one built half window: every vertex on its root planes.
Outcome check_half_window(const CellComplex& cx, std::int64_t unit, const RootSides& sides) {
    Outcome o;
    const BoundaryVertexReport r = check_boundary_vertices(cx, unit, sides);
    o.ok = r.ok() && r.checked > 0;
    o.checked = r.checked;
    o.why = r.ok() ? (r.checked ? "" : "no vertex on the root planes") : r.failures.front();
    for (const LatticePoint& p : cx.positions()) {  // per kind, for the report
        if (!on_checked_planes(p, unit, sides)) continue;
        int k = 0;
        for (int a = 0; a < 3; ++a) k += sides[static_cast<std::size_t>(a)] != 0 && p[a] == 0 ? 1 : 0;
        ++o.per_kind[static_cast<std::size_t>(k - 1)];
    }
    return o;
}

struct HalfWindow {
    const BoundaryType* type = nullptr;
    std::uint64_t pattern = 0;
};

struct Context {
    const TransitionRule& rule;
    const OutsidePolicy& policy;
    tbb::enumerable_thread_specific<detail::TemplateCache>& caches;
};

// Builds and fully checks one half window, keeping its complex in kept if given.
Outcome full_check(const HalfWindow& w, const Context& ctx, CellComplex* kept = nullptr) {
    detail::TemplateCache& cache = ctx.caches.local();
    try {
        CellComplex cx = build_half_window(*w.type, w.pattern, ctx.rule, ctx.policy, cache);
        Outcome o = check_half_window(cx, cache.unit(), w.type->sides);
        if (kept) *kept = std::move(cx);
        return o;
    } catch (const std::exception& e) {
        Outcome o;
        o.why = std::string("not built: ") + e.what();
        return o;
    }
}

// The inside coarse leaves of a half window with what the rule places there (the class
// key's input; throws what the rule throws).
std::vector<PlacedLeaf> coarse_placements(const HalfWindow& w, const Context& ctx) {
    const BoundaryType& t = *w.type;
    std::vector<PlacedLeaf> out;
    for (std::size_t n = 0; n < t.leaves.size(); ++n) {
        if ((w.pattern >> t.own[n]) & 1U) continue;
        PlacedLeaf placed{t.leaves[n], detail::coarse_leaf_context(t.leaves[n], Status{t, ctx.policy, w.pattern, t.leaves[n]}), std::nullopt};
        placed.placement = ctx.rule.place(placed.context);
        out.push_back(std::move(placed));
    }
    return out;
}

detail::OrientedForm half_form(const detail::FormArrays& k, const CubeSymmetry& s) {
    return detail::oriented_form(k, [&](const LatticePoint& p) { return s.apply(p); }, !s.is_rotation());
}

// Every half window's outcome, class by class (class_check.hpp): windows whose root sides
// and inside placements are images under a symmetry about g share a class. The check is
// invariant under a symmetry about g that maps the root sides to the root sides: it reads
// positions only through the root planes x_a = 0 of the root axes and the half-open box the
// sides cut out of [-U, U]^3, both mapped onto their images; cells' outward orientation is
// kept, and the vertex counts per kind are those of the images.
std::vector<Outcome> check_by_class(const std::vector<HalfWindow>& windows, const ElementLibrary& library, const Context& ctx) {
    const detail::PlacementCodes codes(library);
    return detail::check_by_class<detail::BoundaryWindowKey, ComplexBuilder::Parts, Outcome, CellComplex>(
        windows.size(),
        [&](std::size_t i) -> std::optional<std::pair<detail::BoundaryWindowKey, CubeSymmetry>> {
            try {
                const BoundaryType& t = *windows[i].type;
                return detail::boundary_class_key(t.parity, t.sides, coarse_placements(windows[i], ctx), codes);
            } catch (const std::exception&) {
                return std::nullopt;  // the rule threw: the full check reports it
            }
        },
        [&](std::size_t i, CellComplex* keep) { return full_check(windows[i], ctx, keep); },
        [&](std::size_t i) { return half_window_parts(*windows[i].type, windows[i].pattern, ctx.rule, ctx.policy, ctx.caches.local()); },
        [&](std::size_t i, ComplexBuilder::Parts parts) {
            return check_half_window(detail::complex_of(std::move(parts)), ctx.caches.local().unit(), windows[i].type->sides);
        },
        [](const auto& b, const CubeSymmetry& s) { return half_form(detail::FormArrays(b), s); },
        [](const Outcome& o) { return o.ok; });
}

}  // namespace

OutsidePolicy outside_policy(BoundaryPolicy policy) {
    if (policy == BoundaryPolicy::Coarse) return [](const Index3&, const RootSides&, const LatticePoint&) { return OutsideOctant{}; };
    if (policy == BoundaryPolicy::AnyOutside)
        return [](const Index3&, const RootSides&, const LatticePoint&) { return OutsideOctant{OutsideOctant::Kind::Free, {}}; };
    return [](const Index3& o, const RootSides& s, const LatticePoint&) {
        OutsideOctant out{OutsideOctant::Kind::Copy, o};
        for (std::size_t a = 0; a < 3; ++a)  // the reflection across x_a = 0 maps [2c, 2c+2] to [-2c-2, -2c]
            if ((s[a] > 0 && o[a] < 0) || (s[a] < 0 && o[a] >= 0)) out.copy_of[a] = -1 - o[a];
        return out;
    };
}

const char* to_string(BoundaryPolicy policy) {
    return policy == BoundaryPolicy::Coarse ? "coarse" : policy == BoundaryPolicy::Mirror ? "mirror" : "any-outside";
}

BoundaryResult run_compositional_boundary(const TransitionRule& rule, const ElementLibrary& library, BoundaryPolicy policy_kind,
                                          const BoundaryOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const OutsidePolicy policy = options.policy ? options.policy : outside_policy(policy_kind);
    BoundaryResult result;
    result.rule = rule.name();
    result.policy = to_string(policy_kind);
    const auto kinds = boundary_types();
    std::vector<BoundaryType> types(kinds.size());
    std::vector<std::vector<std::uint64_t>> patterns(kinds.size());
    tbb::parallel_for(std::size_t{0}, kinds.size(), [&](std::size_t i) {
        types[i] = boundary_type(kinds[i].first, kinds[i].second, rule, policy);
        patterns[i] = distinct_windows(types[i], rule, policy);
    });
    std::vector<HalfWindow> windows;
    for (std::size_t i = 0; i < types.size(); ++i)
        for (std::uint64_t p : patterns[i]) windows.push_back({&types[i], p});
    tbb::enumerable_thread_specific<detail::TemplateCache> caches([&] { return detail::TemplateCache(library); });
    const Context ctx{rule, policy, caches};
    std::vector<Outcome> outcomes(windows.size());
    std::vector<CellComplex> kept(options.on_window ? windows.size() : 0);  // for the observer
    if (options.on_window)  // every window checked and kept
        tbb::parallel_for(std::size_t{0}, windows.size(), [&](std::size_t w) { outcomes[w] = full_check(windows[w], ctx, &kept[w]); });
    else
        outcomes = check_by_class(windows, library, ctx);
    for (std::size_t i = 0, w = 0; i < types.size(); ++i) {
        BoundaryTypeResult tr{types[i].parity, types[i].sides, 0, static_cast<int>(types[i].leaves.size()),
                              static_cast<int>(types[i].vars.size()), 0, 0, 0};
        for (int s : tr.sides) tr.planes += s != 0 ? 1 : 0;
        for (std::size_t n = 0; n < patterns[i].size(); ++n, ++w) {
            if (options.stop_after_failures && result.failed >= options.stop_after_failures) continue;
            const Outcome& o = outcomes[w];
            ++tr.windows;
            tr.checked_vertices += o.checked;
            for (std::size_t k = 0; k < 3; ++k) result.checked_vertices[k] += o.per_kind[k];
            if (o.ok) ++tr.passed;
            else if (++result.failed <= 10) result.failures.push_back(describe(types[i], patterns[i][n]) + ": " + o.why);
        }
        result.windows += tr.windows;
        result.passed += tr.passed;
        result.types.push_back(tr);
    }
    if (options.on_window) {
        const std::int64_t unit = caches.local().unit();
        for (std::size_t i = 0, w = 0; i < types.size(); ++i)
            for (std::size_t n = 0; n < patterns[i].size(); ++n, ++w)
                options.on_window({&result.types[i], w, describe(types[i], patterns[i][n]), &kept[w], unit, outcomes[w].ok});
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace dualhex
