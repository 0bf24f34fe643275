#pragma once
// The forest of a leaf file's leaves, from the distributed reader's sorted runs
// (leaf_reader.hpp), level by level: the forest starts uniform at the coarsest leaf level;
// in round l every rank sends, for each of its leaves finer than l, the position of the
// leaf's level-l ancestor (once per ancestor: the run is sorted) to the rank owning that
// position in the forest (p8est_comm_find_owner), one MPI_Alltoallv; each rank refines
// the requested quadrants (p8est_refine, not recursive) and the forest is repartitioned.
// No rank ever holds more than its run of leaves and its share of the forest.
#include <cstdint>

#include "forest.hpp"
#include "leaf_reader.hpp"

namespace dualhex::dist {

struct LeafForestStats {
    int rounds = 0;
    std::uint64_t requests_sent = 0, bytes_sent = 0;  ///< by this rank, over all rounds
};

/// Collective. `forest` must be the uniform forest at leaves.min_level.
LeafForestStats refine_to_leaves(Forest& forest, const DistributedLeaves& leaves);

}  // namespace dualhex::dist
