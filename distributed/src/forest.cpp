// The forest, its balance and the pairing fixed point (forest.hpp).
#include "forest.hpp"

#include <p8est_bits.h>
#include <p8est_extended.h>

#include <algorithm>
#include <stdexcept>

namespace dualhex::dist {

p8est_quadrant_t to_quadrant(const Leaf& leaf) {
    p8est_quadrant_t q;
    P8EST_QUADRANT_INIT(&q);
    const int shift = P8EST_MAXLEVEL - leaf.level;
    q.x = static_cast<p4est_qcoord_t>(leaf.i << shift);
    q.y = static_cast<p4est_qcoord_t>(leaf.j << shift);
    q.z = static_cast<p4est_qcoord_t>(leaf.k << shift);
    q.level = static_cast<int8_t>(leaf.level);
    return q;
}

Leaf to_leaf(const p8est_quadrant_t& q) {
    const int shift = P8EST_MAXLEVEL - q.level;
    return {q.level, std::int64_t{q.x} >> shift, std::int64_t{q.y} >> shift, std::int64_t{q.z} >> shift};
}

void init_unmarked(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q) { quadrant_mark(q) = 0; }

namespace {

// Per-quadrant mark in the pairing: 1 = refine in the next round.
int& mark(p8est_quadrant_t* q) { return quadrant_mark(q); }

int refine_marked(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q) { return mark(q); }

// Marks every leaf whose 8-quadrant family is not all leaves here. With families kept on
// one rank (partition for coarsening), a family missing locally is not all leaves.
std::int64_t mark_unpaired(p8est_t* forest) {
    std::int64_t marked = 0;
    if (forest->local_num_quadrants == 0) return 0;
    auto* tree = p8est_tree_array_index(forest->trees, 0);
    sc_array_t* qs = &tree->quadrants;
    const auto n = static_cast<std::ptrdiff_t>(qs->elem_count);
    auto* base = p8est_quadrant_array_index(qs, 0);
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        p8est_quadrant_t* q = base + i;
        mark(q) = 0;
        if (q->level == 0) continue;
        const std::ptrdiff_t first = i - p8est_quadrant_child_id(q);
        const bool paired = first >= 0 && first + 7 < n && p8est_quadrant_is_familyv(base + first);
        if (!paired) {
            mark(q) = 1;
            ++marked;
        }
    }
    return marked;
}

}  // namespace

Forest::Forest(MPI_Comm comm, int level) {
    connectivity_ = p8est_connectivity_new_unitcube();
    forest_ = p8est_new_ext(comm, connectivity_, 0, level, 1, sizeof(int), init_unmarked, nullptr);
}

void Forest::balance_and_pair(Balance balance) {
    const p8est_connect_type_t btype = balance == Balance::Strong ? P8EST_CONNECT_FULL : P8EST_CONNECT_FACE;
    // Fixed point: balance, keep families together, refine the unpaired; until nothing moves.
    for (;;) {
        p8est_balance(forest_, btype, init_unmarked);
        p8est_partition(forest_, 1, nullptr);
        std::int64_t marked = mark_unpaired(forest_), total = 0;
        MPI_Allreduce(&marked, &total, 1, MPI_INT64_T, MPI_SUM, forest_->mpicomm);
        if (total == 0) break;
        ++rounds_;
        p8est_refine(forest_, 0, refine_marked, init_unmarked);
    }
}

Forest::~Forest() {
    if (forest_) p8est_destroy(forest_);
    if (connectivity_) p8est_connectivity_destroy(connectivity_);
}

std::vector<Leaf> Forest::local_leaves() const {
    std::vector<Leaf> out;
    if (forest_->local_num_quadrants == 0) return out;
    auto* tree = p8est_tree_array_index(forest_->trees, 0);
    out.reserve(tree->quadrants.elem_count);
    for (std::size_t i = 0; i < tree->quadrants.elem_count; ++i)
        out.push_back(to_leaf(*p8est_quadrant_array_index(&tree->quadrants, i)));
    return out;
}

int Forest::global_max_level() const {
    int local = 0, global = 0;
    for (const Leaf& l : local_leaves()) local = std::max(local, l.level);
    MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_MAX, forest_->mpicomm);
    return global;
}

}  // namespace dualhex::dist
