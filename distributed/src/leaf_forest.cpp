// The forest of a leaf file, level by level (leaf_forest.hpp).
#include "leaf_forest.hpp"

#include <p8est_communication.h>
#include <p8est_extended.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "morton.hpp"

namespace dualhex::dist {
namespace {

// The level-l ancestors of this run's leaves finer than l, by owner rank.
std::vector<std::vector<std::uint64_t>> requests(p8est_t* forest, const std::vector<SortedLeaf>& run, int level) {
    std::vector<std::vector<std::uint64_t>> out(static_cast<std::size_t>(forest->mpisize));
    const std::uint64_t mask = ~(morton_volume(level) - 1);
    std::uint64_t previous = ~std::uint64_t{0};
    int owner = 0;
    for (const SortedLeaf& l : run) {
        if (l.level <= level) continue;
        const std::uint64_t ancestor = l.position & mask;
        if (ancestor == previous) continue;
        previous = ancestor;
        const p8est_quadrant_t q = to_quadrant(morton_cell(ancestor, level));
        owner = p8est_comm_find_owner(forest, 0, &q, owner);
        out[static_cast<std::size_t>(owner)].push_back(ancestor);
    }
    return out;
}

// One MPI_Alltoallv of the requests; the received positions, sorted.
std::vector<std::uint64_t> exchange(MPI_Comm comm, const std::vector<std::vector<std::uint64_t>>& by_rank,
                                    LeafForestStats& stats) {
    const std::size_t np = by_rank.size();
    std::vector<int> send(np), recv(np), sdispl(np + 1, 0), rdispl(np + 1, 0);
    std::vector<std::uint64_t> flat;
    for (std::size_t r = 0; r < np; ++r) {
        send[r] = static_cast<int>(by_rank[r].size());
        flat.insert(flat.end(), by_rank[r].begin(), by_rank[r].end());
    }
    MPI_Alltoall(send.data(), 1, MPI_INT, recv.data(), 1, MPI_INT, comm);
    for (std::size_t r = 0; r < np; ++r) sdispl[r + 1] = sdispl[r] + send[r], rdispl[r + 1] = rdispl[r] + recv[r];
    std::vector<std::uint64_t> got(static_cast<std::size_t>(rdispl[np]));
    MPI_Alltoallv(flat.data(), send.data(), sdispl.data(), MPI_UINT64_T, got.data(), recv.data(), rdispl.data(),
                  MPI_UINT64_T, comm);
    stats.requests_sent += flat.size();
    stats.bytes_sent += flat.size() * sizeof(std::uint64_t);
    std::sort(got.begin(), got.end());
    return got;
}

struct Round {
    const std::vector<std::uint64_t>* wanted;
    int level;
};

int refine_requested(p8est_t* forest, p4est_topidx_t, p8est_quadrant_t* q) {
    const auto* round = static_cast<const Round*>(forest->user_pointer);
    if (q->level != round->level) return 0;
    return std::binary_search(round->wanted->begin(), round->wanted->end(), morton_position(to_leaf(*q))) ? 1 : 0;
}

}  // namespace

LeafForestStats refine_to_leaves(Forest& forest, const DistributedLeaves& leaves) {
    p8est_t* p4 = forest.get();
    LeafForestStats stats;
    for (int level = leaves.min_level; level < leaves.max_level; ++level) {
        const std::vector<std::uint64_t> wanted = exchange(p4->mpicomm, requests(p4, leaves.leaves, level), stats);
        Round round{&wanted, level};
        p4->user_pointer = &round;
        p8est_refine(p4, 0, refine_requested, init_unmarked);
        p4->user_pointer = nullptr;
        p8est_partition(p4, 0, nullptr);
        ++stats.rounds;
    }
    // The reader checked the tiling, so the forest's leaves are the file's.
    if (p4->global_num_quadrants != leaves.global_count)
        throw std::logic_error("leaf forest: " + std::to_string(p4->global_num_quadrants) + " quadrants for " +
                               std::to_string(leaves.global_count) + " leaves");
    return stats;
}

}  // namespace dualhex::dist
