#pragma once
// One rank's share of the distributed mesh: it installs its leaves and its ghost layer
// (p8est_ghost_new, faces + edges + corners) with contexts gathered from their owners,
// dualizes, and keeps what it owns. A vertex's owner is the lowest rank holding a leaf
// whose closed box contains it (the leaf first in Morton order); that rank holds every
// leaf around the vertex (its own or ghosts), so it sees the vertex's whole star and its
// dual hex is the serial one. Faces count with their smallest vertex, cells with their leaf.
#include <p8est.h>

#include <cstdint>
#include <vector>

#include "dualhex/distributed/canonical.hpp"
#include "dualhex/geometry/hex_output.hpp"
#include "forest.hpp"
#include "level_oracle.hpp"

namespace dualhex::dist {

struct RankOptions {
    Balance balance = Balance::Weak;
    OutsideRoot outside = OutsideRoot::Coarse;
    bool want_piece = false;  ///< build the output piece (hexes of owned vertices)
};

struct RankTimings {
    double ghost = 0, exchange = 0, contexts = 0, install = 0, dual = 0, summary = 0;
};

struct RankMesh {
    CanonicalSummary summary;
    std::uint64_t local_leaves = 0, ghost_leaves = 0, installed_cells = 0;
    ExchangeStats exchange;
    RankTimings ms;
    /// First global id of this rank's vertices (ids are consecutive per rank, in rank
    /// order, by lattice key within a rank).
    std::uint64_t first_vertex_id = 0;
    geometry::HexMesh piece;                    ///< want_piece: hexes of owned vertices
    std::vector<std::uint64_t> piece_vertex_id;  ///< global id of each piece hex's primal vertex
};

/// Collective over the forest's communicator.
[[nodiscard]] RankMesh mesh_rank(const Forest& forest, const RankOptions& options);

}  // namespace dualhex::dist
