#include "dualhex/grid/predicates.hpp"

namespace dualhex {

namespace {

// Grids read from a file name it first, as InputError does: "f.leaves: not paired: ...".
GridCheck failure(const LeafGrid& grid, std::size_t a, std::size_t b, std::string message) {
    if (!grid.source().empty()) message = grid.source() + ": " + message;
    return {false, a, b, std::move(message)};
}

}  // namespace

GridCheck is_paired(const LeafGrid& grid) {
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

// A leaf A (level L) and a leaf B in contact with level(B) <= L-2 always show up as: the
// same-level neighbour cell N of A is neither a leaf, subdivided, nor inside a leaf of
// level L-1. Checking that from the finer side finds every violation.
GridCheck is_balanced(const LeafGrid& grid, Balance mode) {
    for (std::size_t n = 0; n < grid.size(); ++n) {
        const Leaf& leaf = grid.leaf(n);
        if (leaf.level < 2) continue;
        for (const Offset& d : neighbour_offsets(mode)) {
            const Leaf cell = neighbour(leaf, d);
            if (!cell.valid() || grid.find(cell) || grid.is_subdivided(cell) || grid.find(parent(cell))) continue;
            const std::size_t coarse = *grid.locate(cell);
            return failure(grid, n, coarse, std::string(mode == Balance::Strong ? "not strongly" : "not weakly") +
                                          " balanced: leaves " + grid.describe(n) + " and " + grid.describe(coarse) +
                                          " share a " + contact_name(d) + " but differ by " +
                                          std::to_string(leaf.level - grid.leaf(coarse).level) + " levels");
        }
    }
    return {};
}

GridCheck is_strongly_balanced(const LeafGrid& grid) { return is_balanced(grid, Balance::Strong); }
GridCheck is_weakly_balanced(const LeafGrid& grid) { return is_balanced(grid, Balance::Weak); }

}  // namespace dualhex
