// The forest of a surface (surface_forest.hpp).
#include "surface_forest.hpp"

#include <p8est_extended.h>

#include <string>
#include <utility>
#include <vector>

namespace dualhex::dist {
namespace {

// The near triangles of a quadrant's ancestors, root first: chain_[l] is the level-l
// ancestor of the last quadrant asked about, with its near list.
class NearChain {
public:
    explicit NearChain(const geometry::SurfaceRefinement& c) : criterion_(c), all_(c.all_triangles()) {}

    /// The near triangles of q's parent (all triangles for the root).
    const std::vector<int>& parent_near(const Leaf& q) {
        std::size_t keep = 0;  // the chain's prefix that holds q's ancestors
        while (keep < chain_.size() && static_cast<int>(keep) < q.level && chain_[keep].first == ancestor(q, static_cast<int>(keep)))
            ++keep;
        chain_.resize(keep);
        for (int l = static_cast<int>(keep); l < q.level; ++l) {
            const Leaf a = ancestor(q, l);
            chain_.emplace_back(a, criterion_.decide(a, l == 0 ? all_ : chain_.back().second).near);
            ++recomputed;
        }
        return q.level == 0 ? all_ : chain_.back().second;
    }
    /// q was just split with `near`: its children will ask for it.
    void push(const Leaf& q, std::vector<int> near) {
        chain_.resize(static_cast<std::size_t>(q.level));
        chain_.emplace_back(q, std::move(near));
    }

    std::uint64_t recomputed = 0;

private:
    static Leaf ancestor(const Leaf& q, int level) {
        const int up = q.level - level;
        return {level, q.i >> up, q.j >> up, q.k >> up};
    }
    const geometry::SurfaceRefinement& criterion_;
    std::vector<int> all_;
    std::vector<std::pair<Leaf, std::vector<int>>> chain_;
};

struct Context {
    const geometry::SurfaceRefinement& criterion;
    NearChain chain;
    std::int64_t splits = 0, crossing = 0, curvature = 0;
    std::uint64_t decisions = 0;
};

constexpr int kDecidedLeaf = 1;

int refine_by_criterion(p8est_t* forest, p4est_topidx_t, p8est_quadrant_t* q) {
    auto* c = static_cast<Context*>(forest->user_pointer);
    if (quadrant_mark(q) == kDecidedLeaf) return 0;
    const Leaf cell = to_leaf(*q);
    geometry::SurfaceRefinement::Decision d = c->criterion.decide(cell, c->chain.parent_near(cell));
    ++c->decisions;
    if (!d.split) {
        quadrant_mark(q) = kDecidedLeaf;
        c->crossing += d.crosses ? 1 : 0;
        return 0;
    }
    ++c->splits;
    c->curvature += d.by_curvature ? 1 : 0;
    c->chain.push(cell, std::move(d.near));
    return 1;
}

std::int64_t global_sum(MPI_Comm comm, std::int64_t mine) {
    std::int64_t total = 0;
    MPI_Allreduce(&mine, &total, 1, MPI_INT64_T, MPI_SUM, comm);
    return total;
}

}  // namespace

SurfaceForestStats refine_to_surface(Forest& forest, const geometry::SurfaceRefinement& criterion) {
    p8est_t* p4 = forest.get();
    Context c{criterion, NearChain(criterion)};
    SurfaceForestStats stats;
    const std::size_t max_leaves = criterion.options().max_leaves;
    for (;;) {
        const std::int64_t splits_before = c.splits;
        p4->user_pointer = &c;
        p8est_refine(p4, 0, refine_by_criterion, init_unmarked);  // one level: children are decided next round
        p4->user_pointer = nullptr;
        if (global_sum(p4->mpicomm, c.splits - splits_before) == 0) break;
        ++stats.rounds;
        if (static_cast<std::size_t>(p4->global_num_quadrants) > max_leaves)
            throw geometry::OctreeTooLarge("surface octree: more than " + std::to_string(max_leaves) +
                                               " leaves (the size, thickness or curvature criteria ask for too fine cells)",
                                           static_cast<std::size_t>(p4->global_num_quadrants));
        p8est_partition(p4, 0, nullptr);
    }
    stats.octree_leaves = p4->global_num_quadrants;
    stats.crossing_leaves = global_sum(p4->mpicomm, c.crossing);
    stats.curvature_splits = global_sum(p4->mpicomm, c.curvature);
    stats.decisions = c.decisions;
    stats.ancestor_recomputations = c.chain.recomputed;
    return stats;
}

}  // namespace dualhex::dist
