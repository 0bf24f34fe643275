#pragma once
// Which leaf level covers a point, for points anywhere in the root: the one question the
// rule's context asks of the grid (a cell at level l is subdivided iff the leaf at its min
// corner is finer than l; install/leaf_contexts.hpp). Points this rank holds (its leaves
// and ghosts) are answered here; the others are sent to the rank owning them
// (p8est_comm_find_owner: the Morton range of p8est's partition) in one all-to-all round.
#include <mpi.h>
#include <p8est.h>

#include <array>
#include <cstdint>
#include <vector>

#include "dualhex/grid/cell_map.hpp"
#include "dualhex/grid/leaf.hpp"

namespace dualhex::dist {

/// Morton index of a point at p8est's finest quadrant level (qcoords, multiples of 2).
[[nodiscard]] std::uint64_t morton(p4est_qcoord_t x, p4est_qcoord_t y, p4est_qcoord_t z);
/// Min corner of a cell in qcoords.
[[nodiscard]] std::array<p4est_qcoord_t, 3> qcorner(const Leaf& cell);

/// Leaves sorted by the Morton index of their min corner; point location by binary search.
class LeafIndex {
public:
    /// ranks[n]: the rank owning leaves[n] (empty: unknown, rank_of returns -1).
    explicit LeafIndex(const std::vector<Leaf>& leaves, const std::vector<int>& ranks = {});
    /// The leaf containing the point (qcoords), or nullptr.
    [[nodiscard]] const Leaf* locate(p4est_qcoord_t x, p4est_qcoord_t y, p4est_qcoord_t z) const;
    /// The owner of a leaf locate() returned.
    [[nodiscard]] int rank_of(const Leaf* leaf) const {
        return ranks_.empty() ? -1 : ranks_[static_cast<std::size_t>(leaf - leaves_.data())];
    }

private:
    std::vector<Leaf> leaves_;
    std::vector<std::uint64_t> keys_;
    std::vector<int> ranks_;
};

struct ExchangeStats {
    std::uint64_t points_asked = 0;   ///< distinct points this rank needed
    std::uint64_t points_remote = 0;  ///< of which sent to other ranks
    std::uint64_t bytes_sent = 0, bytes_received = 0;
};

class LevelOracle {
public:
    /// Answers every point of `points` (Morton indices): locally from `held` (this rank's
    /// leaves and ghosts) where it can, else from the owner of the point. Collective.
    LevelOracle(p8est_t* forest, const LeafIndex& local, const LeafIndex& held, std::vector<std::uint64_t> points);
    /// Level of the leaf at the min corner of `cell`; throws std::logic_error if that point
    /// was not among those gathered (a context reaching further than planned).
    [[nodiscard]] int level_at(const Leaf& cell) const;
    [[nodiscard]] bool is_subdivided(const Leaf& cell) const { return level_at(cell) > cell.level; }
    [[nodiscard]] const ExchangeStats& stats() const { return stats_; }

private:
    // Keyed by the finest-level cell at the point (CellMap: the grid layer's flat table).
    CellMap<std::int8_t> levels_;
    ExchangeStats stats_;
};

}  // namespace dualhex::dist
