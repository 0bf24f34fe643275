#include "dualhex/grid/predicates.hpp"

#include <algorithm>
#include <array>
#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace dualhex {

namespace {

// Grids read from a file name it first, as InputError does: "f.leaves: not paired: ...".
GridCheck failure(const LeafGrid& grid, std::size_t a, std::size_t b, std::string message) {
    if (!grid.source().empty()) message = grid.source() + ": " + message;
    return {false, a, b, std::move(message)};
}

// Does `holds(item)` hold for every item? Ranges of items are tested in parallel (read-only
// lookups); a failure anywhere stops the others early. The answer is a plain yes or no, the
// same for any number of threads (the serial full passes below name the failure).
template <class Item, class Holds>
bool all_hold(const std::vector<Item>& items, Holds&& holds) {
    std::atomic<bool> failed{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, items.size(), 4096), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t n = r.begin(); n != r.end() && !failed.load(std::memory_order_relaxed); ++n)
            if (!holds(items[n])) failed.store(true, std::memory_order_relaxed);
    });
    return !failed.load();
}

// Paired, with about 2 lookups per leaf instead of 8: a leaf other than its parent's child 0
// only needs child 0 to be a leaf, which in turn checks all its siblings. (Lookups are
// cache misses on large grids; the full pass below runs only to report a failure.)
bool quickly_paired(const LeafGrid& grid) {
    return all_hold(grid.leaves(), [&](const Leaf& leaf) {
        if (leaf.level == 0) return true;
        const auto siblings = children(parent(leaf));
        if (child_index(leaf) != 0) return grid.find(siblings[0]).has_value();
        for (std::size_t c = 1; c < 8; ++c)
            if (!grid.find(siblings[c])) return false;
        return true;
    });
}

}  // namespace

GridCheck is_paired(const LeafGrid& grid) {
    if (quickly_paired(grid)) return {};
    for (std::size_t n = 0; n < grid.size(); ++n) {
        const Leaf& leaf = grid.leaf(n);
        if (leaf.level == 0) continue;
        for (const Leaf& sibling : children(parent(leaf))) {
            if (grid.find(sibling)) continue;
            const std::size_t inside = *grid.leaf_within(sibling);  // tiling: it is subdivided
            return failure(grid, n, inside, "not paired: leaf " + grid.describe(n) + " has sibling " + to_string(sibling) +
                                          " subdivided (it contains leaf " + grid.describe(inside) + ")");
        }
    }
    return {};
}

namespace {

// The leaf inside interior node `node` that is nearest its side `d`: it touches the
// neighbour of `node` in direction `d` through the same kind of contact.
std::size_t leaf_towards(const LeafGrid& grid, Leaf cell, const Offset& d) {
    const int c = (d.dx > 0 ? 1 : 0) | (d.dy > 0 ? 2 : 0) | (d.dz > 0 ? 4 : 0);
    for (;;) {
        if (const auto n = grid.find(cell)) return *n;
        cell = children(cell)[static_cast<std::size_t>(c)];
    }
}

// Balanced, with at most 7 lookups per interior node instead of up to 52: a cell of level
// >= 1 is a node iff its parent is subdivided (a tiling covers every child of an interior
// node), and the parents of a node's neighbours are its parent and at most 7 cells of the
// 2x2x2 block around it. The full pass below runs only to report a failure.
bool quickly_balanced(const LeafGrid& grid, Balance mode) {
    const auto offsets = neighbour_offsets(mode);
    return all_hold(grid.interior_nodes(), [&](const Leaf& node) {
        if (node.level == 0) return true;  // the root has no neighbour
        std::array<Leaf, 8> checked{parent(node)};
        std::size_t n_checked = 1;
        for (const Offset& d : offsets) {
            const Leaf cell = neighbour(node, d);
            if (!cell.valid()) continue;
            const Leaf up = parent(cell);
            if (std::find(checked.begin(), checked.begin() + n_checked, up) != checked.begin() + n_checked) continue;
            if (!grid.is_subdivided(up)) return false;
            checked[n_checked++] = up;
        }
        return true;
    });
}

}  // namespace

// Balanced iff every interior node's same-level neighbours (through the contacts `mode`
// constrains) are nodes too, not strictly inside a coarser leaf (see refinement.cpp).
// One pass over interior nodes; a violation yields the pair (a leaf of the node nearest
// the neighbour, the coarse leaf covering the neighbour), >= 2 levels apart.
GridCheck is_balanced(const LeafGrid& grid, Balance mode) {
    if (quickly_balanced(grid, mode)) return {};
    for (const Leaf& node : grid.interior_nodes()) {
        for (const Offset& d : neighbour_offsets(mode)) {
            const Leaf cell = neighbour(node, d);
            if (!cell.valid() || grid.find(cell) || grid.is_subdivided(cell)) continue;
            const std::size_t coarse = *grid.locate(cell);
            const std::size_t fine = leaf_towards(grid, node, d);
            return failure(grid, fine, coarse, std::string(mode == Balance::Strong ? "not strongly" : "not weakly") +
                                                   " balanced: leaves " + grid.describe(fine) + " and " +
                                                   grid.describe(coarse) + " share a " + contact_name(d) +
                                                   " but differ by " +
                                                   std::to_string(grid.leaf(fine).level - grid.leaf(coarse).level) +
                                                   " levels");
        }
    }
    return {};
}

GridCheck is_strongly_balanced(const LeafGrid& grid) { return is_balanced(grid, Balance::Strong); }
GridCheck is_weakly_balanced(const LeafGrid& grid) { return is_balanced(grid, Balance::Weak); }

}  // namespace dualhex
