// One rank's share (rank_mesh.hpp): ghosts, context exchange, install, dual, ownership.
#include "rank_mesh.hpp"

#include <p8est_ghost.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "contexts.hpp"
#include "dualhex/install/library.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"

namespace dualhex::dist {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct Ghosts {
    std::vector<Leaf> leaves;
    std::vector<int> ranks;
};

Ghosts ghost_layer(p8est_t* forest) {
    p8est_ghost_t* ghost = p8est_ghost_new(forest, P8EST_CONNECT_FULL);
    Ghosts out;
    for (int r = 0; r < forest->mpisize; ++r)
        for (p4est_locidx_t g = ghost->proc_offsets[r]; g < ghost->proc_offsets[r + 1]; ++g) {
            out.leaves.push_back(to_leaf(*p8est_quadrant_array_index(&ghost->ghosts, static_cast<std::size_t>(g))));
            out.ranks.push_back(r);
        }
    p8est_ghost_destroy(ghost);
    return out;
}

// The owner of the vertex at lattice point p: the lowest rank among the leaves whose
// closed box contains p, found at the points p + (+-1/2)(1,1,1) (half-units) inside the
// root. -1 if none of them is this rank's own leaf (a ghost-only vertex: not ours to count).
// Throws if the vertex touches one of our leaves but a leaf around it is not held: the
// ghost layer would then be incomplete and the vertex's star wrong.
class VertexOwners {
public:
    VertexOwners(const LeafIndex& held, int rank, std::int64_t unit, int max_level)
        : held_(&held), rank_(rank), unit_(unit), max_level_(max_level), extent_(unit << max_level) {}

    [[nodiscard]] int owner(const LatticePoint& p) const {
        int best = -1;
        bool mine = false, missing = false;
        for (int d = 0; d < 8; ++d) {
            std::int64_t f[3];
            bool inside = true;
            for (int a = 0; a < 3; ++a) {
                const std::int64_t h = 2 * p[a] + ((d >> a & 1) ? 1 : -1);
                inside = inside && h >= 0 && h < 2 * extent_;
                f[a] = h / (2 * unit_);  // finest-level leaf index (h >= 0 when inside)
            }
            if (!inside) continue;
            const int shift = P8EST_MAXLEVEL - max_level_;
            const Leaf* leaf = held_->locate(static_cast<p4est_qcoord_t>(f[0] << shift), static_cast<p4est_qcoord_t>(f[1] << shift),
                                             static_cast<p4est_qcoord_t>(f[2] << shift));
            if (!leaf) {
                missing = true;
                continue;
            }
            const int r = held_->rank_of(leaf);
            mine = mine || r == rank_;
            best = best < 0 ? r : std::min(best, r);
        }
        if (!mine) return -1;
        if (missing)
            throw std::logic_error("ghost layer incomplete around the vertex at lattice point (" + std::to_string(p.x) + "," +
                                   std::to_string(p.y) + "," + std::to_string(p.z) + ")");
        return best;
    }

private:
    const LeafIndex* held_;
    int rank_;
    std::int64_t unit_;
    int max_level_;
    std::int64_t extent_;
};

InstallResult install_held(const std::vector<Leaf>& held, const std::vector<LeafContext>& contexts, int max_level,
                           Balance balance) {
    const auto library = load_default_element_library();
    // As `dualhex install`: the weak rule is the strong rule plus the MR elements.
    if (balance == Balance::Strong) return install_leaves(held, contexts, max_level, StrongRule(), *library);
    return install_leaves(held, contexts, max_level, WeakRule(), *library);
}

// Global ids of owned vertices: consecutive per rank, by lattice key within the rank.
std::vector<std::uint64_t> number_owned(const CellComplex& k, const std::vector<char>& owned, MPI_Comm comm,
                                        std::uint64_t& first) {
    std::vector<std::uint32_t> mine;
    for (std::size_t v = 0; v < owned.size(); ++v)
        if (owned[v]) mine.push_back(static_cast<std::uint32_t>(v));
    std::sort(mine.begin(), mine.end(), [&](std::uint32_t a, std::uint32_t b) {
        return k.position(VertexHandle(std::size_t{a})) < k.position(VertexHandle(std::size_t{b}));
    });
    std::uint64_t count = mine.size(), offset = 0;
    MPI_Exscan(&count, &offset, 1, MPI_UINT64_T, MPI_SUM, comm);
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (rank == 0) offset = 0;  // MPI_Exscan leaves rank 0's result undefined
    first = offset;
    std::vector<std::uint64_t> ids(owned.size(), ~std::uint64_t{0});
    for (std::size_t n = 0; n < mine.size(); ++n) ids[mine[n]] = offset + n;
    return ids;
}

void build_piece(const InstallResult& in, const ClippedDual& dual, const std::vector<char>& owned,
                 const std::vector<std::uint64_t>& ids, RankMesh& out) {
    const double extent = static_cast<double>(in.unit << in.max_level);
    std::vector<int> remap(dual.points.size(), -1);
    for (std::size_t h = 0; h < dual.hexes.size(); ++h) {
        const VertexHandle v = dual.primal_vertex[h];
        if (!owned[v.index()]) continue;
        std::array<int, 8> hex{};
        for (std::size_t i = 0; i < 8; ++i) {
            const std::uint32_t p = dual.hexes[h][i];
            if (remap[p] < 0) {
                remap[p] = static_cast<int>(out.piece.points.size());
                const RationalPoint& q = dual.points[p];
                out.piece.points.emplace_back(q.coordinate(0, extent), q.coordinate(1, extent), q.coordinate(2, extent));
            }
            hex[i] = remap[p];
        }
        out.piece.hexes.push_back(hex);
        out.piece_vertex_id.push_back(ids[v.index()]);
    }
}

}  // namespace

RankMesh mesh_rank(const Forest& forest, const RankOptions& options) {
    p8est_t* p4 = forest.get();
    RankMesh out;
    auto t0 = Clock::now();
    const std::vector<Leaf> local = forest.local_leaves();
    const Ghosts ghosts = ghost_layer(p4);
    out.local_leaves = local.size();
    out.ghost_leaves = ghosts.leaves.size();
    std::vector<Leaf> held = local;  // own leaves first: the summary counts [0, local)
    held.insert(held.end(), ghosts.leaves.begin(), ghosts.leaves.end());
    std::vector<int> ranks(local.size(), p4->mpirank);
    ranks.insert(ranks.end(), ghosts.ranks.begin(), ghosts.ranks.end());
    const LeafIndex local_index(local), held_index(held, ranks);
    const int max_level = forest.global_max_level();
    out.ms.ghost = ms_since(t0);

    t0 = Clock::now();
    const LevelOracle oracle(p4, local_index, held_index, context_points(held));
    out.exchange = oracle.stats();
    out.ms.exchange = ms_since(t0);

    t0 = Clock::now();
    const std::vector<LeafContext> contexts = gather_contexts(held, oracle, options.outside);
    out.ms.contexts = ms_since(t0);

    t0 = Clock::now();
    const InstallResult installed = install_held(held, contexts, max_level, options.balance);
    out.installed_cells = installed.complex.n_cells();
    out.ms.install = ms_since(t0);

    t0 = Clock::now();
    const std::int64_t extent = installed.unit << max_level;
    const Incidence incidence(installed.complex);
    const ClippedDual dual = clipped_dual(installed.complex, incidence, {0, 0, 0}, {extent, extent, extent});
    out.ms.dual = ms_since(t0);

    t0 = Clock::now();
    const VertexOwners owners(held_index, p4->mpirank, installed.unit, max_level);
    std::vector<char> owned(installed.complex.n_vertices(), 0);
    for (std::size_t v = 0; v < owned.size(); ++v)
        owned[v] = owners.owner(installed.complex.position(VertexHandle(v))) == p4->mpirank ? 1 : 0;
    out.summary = summarize(installed, incidence, dual, {0, local.size(), [&](VertexHandle v) { return owned[v.index()] != 0; }});
    const std::vector<std::uint64_t> ids = number_owned(installed.complex, owned, p4->mpicomm, out.first_vertex_id);
    if (options.want_piece) build_piece(installed, dual, owned, ids, out);
    out.ms.summary = ms_since(t0);
    return out;
}

}  // namespace dualhex::dist
