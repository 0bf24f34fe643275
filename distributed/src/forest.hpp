#pragma once
// The p8est forest (one tree, the unit cube, no periodicity), refined by a builder
// (leaf_forest.hpp: to a leaf file's leaves; surface_forest.hpp: by the surface octree's
// criterion), then balanced by p8est (strong = P8EST_CONNECT_FULL: faces, edges and
// corners; weak = P8EST_CONNECT_FACE), paired by a fixed point (refine every leaf whose
// family is not all leaves, rebalance) and partitioned with families kept on one rank.
// GPL-2.0-or-later through p4est (distributed/README.md).
#include <mpi.h>
#include <p8est.h>

#include <cstdint>
#include <vector>

#include "dualhex/grid/leaf.hpp"
#include "dualhex/grid/predicates.hpp"

namespace dualhex::dist {

/// Finest level a p8est quadrant may have (P8EST_QMAXLEVEL); deeper leaves are refused.
inline constexpr int kForestMaxLevel = P8EST_QMAXLEVEL;

/// Owns the connectivity and the forest. Each quadrant carries one int (the builders'
/// and the pairing's mark).
class Forest {
public:
    /// Uniform at `level`, spread over the ranks (level 0: one quadrant, on one rank).
    Forest(MPI_Comm comm, int level);
    ~Forest();
    Forest(const Forest&) = delete;
    Forest& operator=(const Forest&) = delete;

    /// p8est_balance, then the pairing fixed point (each round: partition keeping families,
    /// mark, refine, balance) until no rank marks a leaf.
    void balance_and_pair(Balance balance);

    [[nodiscard]] p8est_t* get() const { return forest_; }
    /// The rank's leaves in Morton order.
    [[nodiscard]] std::vector<Leaf> local_leaves() const;
    /// Global number of leaves and the finest level over all ranks.
    [[nodiscard]] std::int64_t global_leaves() const { return forest_->global_num_quadrants; }
    [[nodiscard]] int global_max_level() const;
    /// Rounds of the pairing fixed point (each: mark, refine, balance, partition).
    [[nodiscard]] int pairing_rounds() const { return rounds_; }

private:
    p8est_connectivity_t* connectivity_ = nullptr;
    p8est_t* forest_ = nullptr;
    int rounds_ = 0;
};

/// The int each quadrant carries.
[[nodiscard]] inline int& quadrant_mark(p8est_quadrant_t* q) { return *static_cast<int*>(q->p.user_data); }
/// p8est init callback: mark 0.
void init_unmarked(p8est_t*, p4est_topidx_t, p8est_quadrant_t* q);

/// A leaf as a p8est quadrant and back (tree 0).
[[nodiscard]] p8est_quadrant_t to_quadrant(const Leaf& leaf);
[[nodiscard]] Leaf to_leaf(const p8est_quadrant_t& q);

}  // namespace dualhex::dist
