#include "dualhex/grid/leaf_grid.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dualhex/grid/input_error.hpp"

namespace dualhex {

LeafGrid::LeafGrid() : LeafGrid(std::vector<Leaf>{Leaf{}}) {}

LeafGrid::LeafGrid(std::vector<Leaf> leaves, std::string source, std::vector<int> lines)
    : leaves_(std::move(leaves)), lines_(std::move(lines)), source_(std::move(source)), nodes_(2 * leaves_.size()) {
    if (!lines_.empty() && lines_.size() != leaves_.size())
        throw InputError(source_, 0, "internal: " + std::to_string(lines_.size()) + " line numbers for " +
                                         std::to_string(leaves_.size()) + " leaves");
    if (leaves_.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw InputError(source_, 0, "too many leaves (" + std::to_string(leaves_.size()) + ")");
    index_leaves();
    index_ancestors();
    find_gap();
}

// Range and duplicate checks, in input order so the first bad line is reported.
void LeafGrid::index_leaves() {
    for (std::size_t n = 0; n < leaves_.size(); ++n) {
        const Leaf& l = leaves_[n];
        if (!l.valid()) {
            const std::string why = l.level < 0 || l.level > kMaxLevel
                                        ? "level must be in [0, " + std::to_string(kMaxLevel) + "]"
                                        : "coordinates must be in [0, 2^" + std::to_string(l.level) + ")";
            throw InputError(source_, line(n), "invalid leaf " + to_string(l) + ": " + why);
        }
        const auto [value, inserted] = nodes_.insert(l, static_cast<std::int32_t>(n));
        if (!inserted)
            throw InputError(source_, line(n), "duplicate leaf " + describe(n) + ", first given as " +
                                                   describe(static_cast<std::size_t>(*value)));
    }
}

// Marks every proper ancestor of every leaf as interior. Leaves are disjoint or nested,
// so the leaves overlap iff some leaf is an ancestor of another: met while climbing.
void LeafGrid::index_ancestors() {
    for (std::size_t n = 0; n < leaves_.size(); ++n) {
        for (int level = leaves_[n].level - 1; level >= 0; --level) {
            const Leaf up = ancestor(leaves_[n], level);
            const auto [value, inserted] = nodes_.insert(up, -1 - static_cast<std::int32_t>(n));
            if (*value >= 0)
                throw InputError(source_, line(n), "overlap: leaf " + describe(n) + " lies inside leaf " +
                                                       describe(static_cast<std::size_t>(*value)));
            if (!inserted) break;  // the rest of the chain is already indexed
        }
    }
}

// With no overlap, the leaves tile iff every child of every interior node is known
// (a leaf or interior). Checked first over ranges of the map's slots in parallel (a plain
// yes or no); only a grid with a gap is walked from the root, serially, so the gap named
// (the first unknown child met, a maximal uncovered region) is the same for any number of
// threads. Every interior node is reached by that walk (its ancestors are all interior).
void LeafGrid::find_gap() const {
    const Leaf root{};
    if (!nodes_.contains(root)) throw InputError(source_, 0, "gap: no leaves, the root cube 0 0 0 0 is not covered");
    std::atomic<bool> gap{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nodes_.slot_count(), 1 << 14), [&](const auto& r) {
        nodes_.for_each_in(r.begin(), r.end(), [&](const Leaf& cell, std::int32_t v) {
            if (v >= 0 || gap.load(std::memory_order_relaxed)) return;
            for (const Leaf& child : children(cell))
                if (!nodes_.contains(child)) gap.store(true, std::memory_order_relaxed);
        });
    });
    if (!gap.load()) return;
    std::vector<Leaf> stack{root};
    while (!stack.empty()) {
        const Leaf cell = stack.back();
        stack.pop_back();
        if (*nodes_.find(cell) >= 0) continue;
        for (const Leaf& child : children(cell)) {
            if (!nodes_.contains(child))
                throw InputError(source_, 0, "gap: cell " + to_string(child) + " (level " +
                                                 std::to_string(child.level) + ") is not covered by any leaf");
            stack.push_back(child);
        }
    }
}

std::optional<std::size_t> LeafGrid::find(const Leaf& cell) const {
    if (!cell.valid()) return std::nullopt;
    const auto* v = nodes_.find(cell);
    if (v == nullptr || *v < 0) return std::nullopt;
    return static_cast<std::size_t>(*v);
}

bool LeafGrid::is_subdivided(const Leaf& cell) const {
    if (!cell.valid()) return false;
    const auto* v = nodes_.find(cell);
    return v != nullptr && *v < 0;
}

std::optional<std::size_t> LeafGrid::locate(const Leaf& cell) const {
    if (!cell.valid()) return std::nullopt;
    for (int level = cell.level; level >= 0; --level) {
        const auto* v = nodes_.find(ancestor(cell, level));
        if (v == nullptr) continue;
        if (*v >= 0) return static_cast<std::size_t>(*v);
        return std::nullopt;  // an interior node: `cell` is subdivided
    }
    return std::nullopt;
}

std::optional<std::size_t> LeafGrid::leaf_within(const Leaf& cell) const {
    if (!cell.valid()) return std::nullopt;
    if (const auto* v = nodes_.find(cell)) return static_cast<std::size_t>(*v >= 0 ? *v : -1 - *v);
    return locate(cell);
}

std::vector<Leaf> LeafGrid::interior_nodes() const {
    std::vector<Leaf> out;
    out.reserve(leaves_.size() / 7 + 1);
    nodes_.for_each([&](const Leaf& cell, std::int32_t v) {
        if (v < 0) out.push_back(cell);
    });
    return out;
}

std::vector<std::size_t> LeafGrid::counts_per_level() const {
    std::vector<std::size_t> counts(static_cast<std::size_t>(max_level()) + 1, 0);
    for (const Leaf& l : leaves_) ++counts[static_cast<std::size_t>(l.level)];
    return counts;
}

int LeafGrid::min_level() const {
    int m = kMaxLevel;
    for (const Leaf& l : leaves_) m = std::min(m, l.level);
    return m;
}

int LeafGrid::max_level() const {
    int m = 0;
    for (const Leaf& l : leaves_) m = std::max(m, l.level);
    return m;
}

std::string LeafGrid::describe(std::size_t n) const {
    std::string s = to_string(leaves_[n]);
    if (line(n) > 0) s += " (line " + std::to_string(line(n)) + ")";
    return s;
}

}  // namespace dualhex
