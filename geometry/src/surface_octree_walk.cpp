#include "surface_octree_walk.hpp"

#include <array>
#include <atomic>
#include <string>
#include <utility>

#include <tbb/parallel_for.h>

namespace dualhex::geometry::detail {

namespace {

// The decision's leaf or split recorded in `into`; true iff `cell` is a leaf.
bool record(const SurfaceRefinement::Decision& d, const Leaf& cell, WalkResult& into) {
    if (d.split) {
        into.curvature_splits += d.by_curvature ? 1 : 0;
        return false;
    }
    into.leaves.push_back(cell);
    into.crossing += d.crosses ? 1 : 0;
    return true;
}

// The serial recursion: the budget counts the leaves emitted before each split.
struct SerialBuilder {
    const SurfaceRefinement& criterion;
    WalkResult out;

    void visit(const Leaf& cell, const std::vector<int>& parent_near) {
        const SurfaceRefinement::Decision d = criterion.decide(cell, parent_near);
        if (record(d, cell, out)) return;
        const std::size_t max_leaves = criterion.options().max_leaves;
        if (out.leaves.size() + 8 > max_leaves)
            throw OctreeTooLarge("surface octree: more than " + std::to_string(max_leaves) +
                                     " leaves (the size, thickness or curvature criteria ask for too fine cells)",
                                 out.leaves.size() + 8);
        for (const Leaf& child : children(cell)) visit(child, d.near);
    }
};

// Thrown by a parallel task once the octree has more than max_leaves leaves.
struct OverBudget {};

// The parallel walk. Every split adds 7 leaves to a shared count; once it exceeds the
// budget, the octree (which only grows) is certainly larger than max_leaves, and the
// serial walk decides what to report. Below the budget the serial walk would not throw:
// a split's 8 children follow the leaves before it, so that count + 8 <= the total.
class ParallelBuilder {
public:
    explicit ParallelBuilder(const SurfaceRefinement& c) : criterion_(c) {}

    void visit(const Leaf& cell, const std::vector<int>& parent_near, WalkResult& into) {
        const SurfaceRefinement::Decision d = criterion_.decide(cell, parent_near);
        if (record(d, cell, into)) return;
        if (leaves_.fetch_add(7, std::memory_order_relaxed) + 7 > criterion_.options().max_leaves) throw OverBudget{};
        const auto kids = children(cell);
        if (cell.level >= kParallelLevels) {
            for (const Leaf& child : kids) visit(child, d.near, into);
            return;
        }
        std::array<WalkResult, 8> parts;  // appended in child order: the serial order
        tbb::parallel_for(0, 8, [&](int c) { visit(kids[static_cast<std::size_t>(c)], d.near, parts[static_cast<std::size_t>(c)]); });
        for (WalkResult& part : parts) {
            into.leaves.insert(into.leaves.end(), part.leaves.begin(), part.leaves.end());
            into.crossing += part.crossing;
            into.curvature_splits += part.curvature_splits;
        }
    }

private:
    const SurfaceRefinement& criterion_;
    std::atomic<std::size_t> leaves_{1};  // the root
};

}  // namespace

WalkResult serial_walk(const SurfaceRefinement& criterion) {
    SerialBuilder b{criterion, {}};
    b.visit(Leaf{}, criterion.all_triangles());
    return std::move(b.out);
}

WalkResult parallel_walk(const SurfaceRefinement& criterion) {
    try {
        ParallelBuilder b(criterion);
        WalkResult out;
        b.visit(Leaf{}, criterion.all_triangles(), out);
        return out;
    } catch (const OverBudget&) {
        return serial_walk(criterion);
    }
}

}  // namespace dualhex::geometry::detail
