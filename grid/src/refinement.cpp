#include "dualhex/grid/refinement.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include <tbb/parallel_for.h>

#include "node_levels.hpp"

namespace dualhex {

namespace {

using detail::CellKey128;
using detail::NodeLevels;

// The least refinement as a closure. A refinement is its set of interior nodes; the least
// one satisfying the conditions is the smallest set containing the input's interior nodes
// and closed under
//   - parent: a node's parent is a node (it is an octree);
//   - balance: for an interior node X of level L, the parents of X's same-level neighbours
//     (through the contacts `mode` constrains) are interior, so those neighbours are nodes
//     and no leaf beside X is two levels coarser than X's children (this is the condition
//     of predicates.cpp; every split it forces is forced, so the result is the least one);
//   - pairing: X's siblings are interior (no node has both leaf and interior children).
// Parent and balance go one level up and pairing stays on the level, so one sweep from
// the finest level to the root closes the set: when level L is reached nothing can add
// to it any more. Each level is a sorted array of 128-bit keys (node_levels.hpp), found in
// parallel and sorted: the same arrays, so the same grid, for any number of threads.
// (Sundar, Sampath and Biros 2008 balance linear octrees by sorting too; this is the plain
// level-by-level closure, not their algorithm.)
struct Rules {
    std::optional<Balance> balance;
    bool pair = false;
};

// The parents of X's same-level neighbours: with s_a = -1 if X is on the low side of its
// parent along axis a (even coordinate), +1 otherwise, a neighbour X + d has parent
// parent(X) + e with e_a = s_a iff d_a = s_a, else 0. The 26 directions give all 8 such
// e (Strong); the 6 faces give e = 0 and the three s_a along one axis (Weak). Cells
// outside the root are left out (level -1).
// When X's siblings are all nodes (`family`: the level is closed under siblings), a cell
// p + e with e_a = 0 is found by every sibling whatever its s_a; only the one with s_a = -1
// on every such axis keeps it, so a family gives each of its 27 (Strong) or 7 (Weak)
// cells once (and the parent 8 times, named by every node for the parent rule) instead of
// 64 or 32 candidates to sort.
std::array<Leaf, 8> neighbour_parents(const Leaf& x, Balance mode, bool family) {
    const Leaf p = parent(x);
    const std::int64_t s[3] = {x.i % 2 ? 1 : -1, x.j % 2 ? 1 : -1, x.k % 2 ? 1 : -1};
    std::array<Leaf, 8> out;
    for (int e = 0; e < 8; ++e) {
        const bool on[3] = {(e & 1) != 0, (e & 2) != 0, (e & 4) != 0};
        bool keep = mode == Balance::Strong || on[0] + on[1] + on[2] <= 1;
        for (int a = 0; a < 3; ++a) keep = keep && (on[a] || !family || s[a] == -1);
        const Leaf c{p.level, p.i + (on[0] ? s[0] : 0), p.j + (on[1] ? s[1] : 0), p.k + (on[2] ? s[2] : 0)};
        out[static_cast<std::size_t>(e)] = keep && c.valid() ? c : Leaf{-1, 0, 0, 0};
    }
    return out;
}

// The cells that level `l`'s nodes force one level up: their parents and, with a balance
// rule, their neighbours' parents.
std::vector<CellKey128> forced_above(const std::vector<CellKey128>& nodes, int l, const Rules& rules) {
    if (!rules.balance) {
        std::vector<CellKey128> out(nodes.size());
        tbb::parallel_for(std::size_t{0}, nodes.size(),
                          [&](std::size_t n) { out[n] = detail::key_of(parent(detail::cell_of(l, nodes[n]))); });
        return out;
    }
    constexpr CellKey128 kNone = ~CellKey128{0};  // no cell has this key (coordinates < 2^30)
    std::vector<CellKey128> out(8 * nodes.size());
    tbb::parallel_for(std::size_t{0}, nodes.size(), [&](std::size_t n) {
        const Leaf x = detail::cell_of(l, nodes[n]);
        const auto cells = neighbour_parents(x, *rules.balance, rules.pair);
        out[8 * n] = detail::key_of(parent(x));  // e = 0 may be another sibling's: the parent rule needs it here
        for (std::size_t c = 1; c < 8; ++c) out[8 * n + c] = cells[c].level < 0 ? kNone : detail::key_of(cells[c]);
    });
    out.erase(std::remove(out.begin(), out.end(), kNone), out.end());
    return out;
}

// Level `l` closed under siblings: every child of every node's parent.
void close_under_siblings(NodeLevels& nodes, int l) {
    const auto& level = nodes.level(l);
    std::vector<CellKey128> siblings(8 * level.size());
    tbb::parallel_for(std::size_t{0}, level.size(), [&](std::size_t n) {
        const auto cells = children(parent(detail::cell_of(l, level[n])));
        for (std::size_t c = 0; c < 8; ++c) siblings[8 * n + c] = detail::key_of(cells[c]);
    });
    nodes.add(l, std::move(siblings));
}

LeafGrid least_refinement(const LeafGrid& grid, const Rules& rules) {
    NodeLevels nodes(grid);
    for (int l = nodes.deepest(); l >= 1; --l) {
        if (rules.pair) close_under_siblings(nodes, l);
        nodes.add(l - 1, forced_above(nodes.level(l), l, rules));
    }
    return LeafGrid(nodes.leaves());
}

}  // namespace

LeafGrid balance(const LeafGrid& grid, Balance mode) { return least_refinement(grid, {mode, false}); }

LeafGrid pair_only(const LeafGrid& grid) { return least_refinement(grid, {std::nullopt, true}); }

LeafGrid pair(const LeafGrid& grid, Balance mode) { return least_refinement(grid, {mode, true}); }

}  // namespace dualhex
