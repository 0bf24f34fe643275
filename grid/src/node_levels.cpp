#include "node_levels.hpp"

#include <algorithm>
#include <iterator>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

namespace dualhex::detail {

void sort_unique(std::vector<CellKey128>& keys) {
    tbb::parallel_sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

NodeLevels::NodeLevels(const LeafGrid& grid) : levels_(static_cast<std::size_t>(std::max(grid.max_level(), 1))) {
    std::vector<std::vector<CellKey128>> found(levels_.size());
    // Child 0 names its parent once; a parent whose child 0 is subdivided is found again
    // as the parent of that interior node (the refinements' parent rule).
    for (const Leaf& leaf : grid.leaves())
        if (leaf.level > 0 && child_index(leaf) == 0)
            found[static_cast<std::size_t>(leaf.level - 1)].push_back(key_of(parent(leaf)));
    for (int l = 0; l <= deepest(); ++l) add(l, std::move(found[static_cast<std::size_t>(l)]));
}

void NodeLevels::add(int l, std::vector<CellKey128> keys) {
    sort_unique(keys);
    auto& mine = level(l);
    if (mine.empty()) {
        mine = std::move(keys);
        return;
    }
    std::vector<CellKey128> merged;  // the level is sorted already: merge, do not sort it again
    merged.reserve(mine.size() + keys.size());
    std::set_union(mine.begin(), mine.end(), keys.begin(), keys.end(), std::back_inserter(merged));
    mine = std::move(merged);
}

std::vector<Leaf> NodeLevels::leaves() const {
    if (levels_.front().empty()) return {Leaf{}};
    std::vector<Leaf> out;
    for (int l = 1; l <= deepest() + 1; ++l) {
        const auto& parents = levels_[static_cast<std::size_t>(l - 1)];
        std::vector<CellKey128> kids(8 * parents.size());
        tbb::parallel_for(std::size_t{0}, parents.size(), [&](std::size_t n) {
            const auto cells = children(cell_of(l - 1, parents[n]));
            for (std::size_t c = 0; c < 8; ++c) kids[8 * n + c] = key_of(cells[c]);
        });
        tbb::parallel_sort(kids.begin(), kids.end());  // no repeats: distinct parents, distinct children
        static const std::vector<CellKey128> kNone;
        const auto& interior = l <= deepest() ? levels_[static_cast<std::size_t>(l)] : kNone;
        std::vector<CellKey128> leaf_keys;
        leaf_keys.reserve(kids.size());
        std::set_difference(kids.begin(), kids.end(), interior.begin(), interior.end(), std::back_inserter(leaf_keys));
        for (CellKey128 k : leaf_keys) out.push_back(cell_of(l, k));
    }
    return out;
}

}  // namespace dualhex::detail
