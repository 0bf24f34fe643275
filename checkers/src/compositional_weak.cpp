// The weak rule's reduction facts (compositional_weak.hpp), computed over every context
// the rule can tell apart, and the grid that attains the largest level spread at a point.
#include "dualhex/checkers/compositional_weak.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "dualhex/grid/refinement.hpp"
#include "dualhex/install/element_templates.hpp"
#include "dualhex/schemes/signature_rule.hpp"

namespace dualhex {
namespace {

std::uint64_t bit(int i, int j, int k) { return std::uint64_t{1} << LeafContext::neighbourhood_bit(i, j, k); }

// A context's outcome: the placement, or "refused" (the rule threw).
struct Outcome {
    bool refused = false;
    std::optional<Placement> placement;
    bool operator==(const Outcome&) const = default;
};

Outcome outcome(const TransitionRule& rule, const LeafContext& ctx) {
    try {
        return {false, rule.place(ctx)};
    } catch (const std::exception&) {
        return {true, std::nullopt};
    }
}

bool at_p(int b) {
    const int i = (b & 3) - 2, j = ((b >> 2) & 3) - 2, k = ((b >> 4) & 3) - 2;
    return i >= -1 && i <= 0 && j >= -1 && j <= 0 && k >= -1 && k <= 0;
}

// Inner a-edge concave: the octants across both adjacent inner faces are fine.
std::uint8_t concave_edges(const LeafContext& ctx) {
    std::uint8_t out = 0;
    for (int a = 0; a < 3; ++a) {
        int fb[3] = {0, 0, 0}, fd[3] = {0, 0, 0};
        fb[(a + 1) % 3] = -1;
        fd[(a + 2) % 3] = -1;
        if (ctx.fine(fb[0], fb[1], fb[2]) && ctx.fine(fd[0], fd[1], fd[2])) out |= static_cast<std::uint8_t>(1U << a);
    }
    return out;
}

}  // namespace

WeakLemmaResult check_weak_lemmas(const TransitionRule& rule) {
    WeakLemmaResult r;
    r.rule = rule.name();
    const std::uint64_t own = bit(0, 0, 0);
    std::vector<int> reach, far;  // reach bits other than the own octant; those not at P
    for (int b = 0; b < 64; ++b) {
        if (!((rule.reach() >> b) & 1U)) continue;
        ++r.reach_octants;
        if ((std::uint64_t{1} << b) == own) continue;
        reach.push_back(b);
        if (!at_p(b)) far.push_back(b);
    }
    const auto context = [](const std::vector<int>& bits, std::uint64_t a, unsigned edges) {
        LeafContext ctx;
        for (std::size_t i = 0; i < bits.size(); ++i)
            if ((a >> i) & 1U) ctx.neighbourhood |= std::uint64_t{1} << bits[i];
        ctx.edge_two_finer = static_cast<std::uint8_t>(edges);
        return ctx;
    };
    // The lemma: nothing fine at P, every value of the far bits and of the edge bits.
    for (std::uint64_t a = 0; a < (std::uint64_t{1} << far.size()); ++a)
        for (unsigned e = 0; e < 8; ++e) {
            ++r.lemma_contexts;
            const Outcome o = outcome(rule, context(far, a, e));
            if (!o.refused && !o.placement) ++r.lemma_plain;
        }
    // The visible domain.
    for (std::uint64_t a = 0; a < (std::uint64_t{1} << reach.size()); ++a)
        for (unsigned e = 0; e < 8; ++e) {
            const LeafContext ctx = context(reach, a, e);
            ++r.visible_contexts;
            const Outcome o = outcome(rule, ctx);
            if (o.refused) ++r.refused;
            else if (o.placement) ++r.placed, ++r.elements[o.placement->element];
            else ++r.plain;
            const std::uint8_t concave = concave_edges(ctx);
            if (ctx.edge_two_finer & ~concave) {
                ++r.nonconcave_contexts;
                LeafContext cleared = ctx;
                cleared.edge_two_finer &= concave;
                if (outcome(rule, cleared) == o) ++r.nonconcave_ignored;
            } else if (ctx.edge_two_finer) {
                LeafContext cleared = ctx;
                cleared.edge_two_finer = 0;
                if (!(outcome(rule, cleared) == o)) ++r.mr_contexts;
            }
        }
    return r;
}

LeafGrid spread_three_grid(int m, int corner) {
    if (m < 2 || m > 12) throw std::invalid_argument("spread_three_grid: m must be in 2..12");
    if (corner < 0 || corner > 7) throw std::invalid_argument("spread_three_grid: corner must be in 0..7");
    const std::int64_t n = std::int64_t{1} << m, p = n / 2;
    const auto side = [corner](int a) { return (corner >> a) & 1; };  // 1: the deep cells lie at x_a >= P
    const auto deep = [&](int level) {  // the level-`level` cell at P on the deep side
        const std::int64_t q = p << (level - m);
        return Leaf{level, q - 1 + side(0), q - 1 + side(1), q - 1 + side(2)};
    };
    std::vector<Leaf> leaves;
    for (std::int64_t i = 0; i < n; ++i)
        for (std::int64_t j = 0; j < n; ++j)
            for (std::int64_t k = 0; k < n; ++k)
                if (Leaf{m, i, j, k} != deep(m)) leaves.push_back({m, i, j, k});
    for (int level = m + 1; level <= m + 3; ++level)
        for (const Leaf& child : children(deep(level - 1)))
            if (child != deep(level) || level == m + 3) leaves.push_back(child);
    return pair(LeafGrid(std::move(leaves)), Balance::Weak);
}

std::vector<WeakWindowReads> weak_window_reads() {
    using detail::Index3;
    const auto none = [](const Index3&) { return false; };
    std::vector<WeakWindowReads> out;
    for (int t = 0; t < 8; ++t) {
        WeakWindowReads r;
        r.parity = {t & 1, (t >> 1) & 1, (t >> 2) & 1};
        std::set<Index3> octants;
        std::map<Index3, int> readers;  // level-m cell -> number of leaves reading it
        std::set<LatticePoint> points;
        for (int n = 0; n < 8; ++n) {
            const LatticePoint cell{r.parity[0] - 1 + (n & 1), r.parity[1] - 1 + ((n >> 1) & 1), r.parity[2] - 1 + ((n >> 2) & 1)};
            // the level-m leaf in this cell: its octants (R(t)), its own cell and 3 edge cells
            const LeafContext ctx = detail::coarse_leaf_context(cell, none);
            std::set<Index3> mine{{cell.x, cell.y, cell.z}};
            for (int b = 0; b < 64; ++b)
                if ((strong_reach() >> b) & 1U)
                    octants.insert(detail::world_octant(ctx, {(b & 3) - 2, ((b >> 2) & 3) - 2, ((b >> 4) & 3) - 2}));
            for (int a = 0; a < 3; ++a) {
                Index3 e{};
                for (int u = 0; u < 3; ++u) {
                    const int local = u == a ? 0 : -1;
                    e[static_cast<std::size_t>(u)] =
                        ctx.application_point[u] + (ctx.direction[static_cast<std::size_t>(u)] > 0 ? local : -local - 1);
                }
                mine.insert(e);
            }
            for (const Index3& c : mine) ++readers[c];
            // its 8 level-(m+1) children: their own cell and their 10 reach cells (level m)
            for (int k = 0; k < 8; ++k) {
                const LatticePoint child = cell * 2 + LatticePoint{k & 1, (k >> 1) & 1, (k >> 2) & 1};
                const LeafContext cc = detail::coarse_leaf_context(child, none);
                points.insert(cc.application_point);
                std::set<Index3> theirs{{cell.x, cell.y, cell.z}};
                for (int b = 0; b < 64; ++b)
                    if ((strong_reach() >> b) & 1U)
                        theirs.insert(detail::world_octant(cc, {(b & 3) - 2, ((b >> 2) & 3) - 2, ((b >> 4) & 3) - 2}));
                for (const Index3& c : theirs) ++readers[c];
            }
        }
        r.octants = static_cast<int>(octants.size());
        r.cells = static_cast<int>(readers.size());
        for (const auto& [c, k] : readers) r.shared_cells += k > 1 ? 1 : 0;
        r.application_points = static_cast<int>(points.size());
        out.push_back(r);
    }
    return out;
}

std::vector<int> levels_at(const LeafGrid& grid, const std::array<std::int64_t, 3>& p, int level) {
    std::vector<int> out;
    for (const Leaf& leaf : grid.leaves()) {
        bool in = true;
        for (int a = 0; a < 3; ++a) {
            // leaf [c, c+1] * 2^-L contains p * 2^-level  <=>  c 2^level <= p 2^L <= (c+1) 2^level
            const std::int64_t x = p[static_cast<std::size_t>(a)] << leaf.level, c = leaf.coord(a);
            in = in && (c << level) <= x && x <= ((c + 1) << level);
        }
        if (in) out.push_back(leaf.level);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace dualhex
