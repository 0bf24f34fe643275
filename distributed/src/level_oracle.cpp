// Point levels: local answers, then one all-to-all round for the rest (level_oracle.hpp).
#include "level_oracle.hpp"

#include <p8est_communication.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dualhex::dist {

namespace {

// qcoords of p8est's finest quadrants are even: 18 significant bits per axis.
constexpr int kBits = P8EST_QMAXLEVEL;

std::array<p4est_qcoord_t, 3> unmorton(std::uint64_t m) {
    std::array<p4est_qcoord_t, 3> c{0, 0, 0};
    for (int b = 0; b < kBits; ++b)
        for (int a = 0; a < 3; ++a)
            if ((m >> (3 * b + a)) & 1U) c[static_cast<std::size_t>(a)] |= p4est_qcoord_t{1} << (b + 1);
    return c;
}

// The finest-level cell whose min corner is the point: the oracle's key.
Leaf finest_cell(const std::array<p4est_qcoord_t, 3>& c) {
    const int shift = P8EST_MAXLEVEL - P8EST_QMAXLEVEL;
    return {P8EST_QMAXLEVEL, std::int64_t{c[0]} >> shift, std::int64_t{c[1]} >> shift, std::int64_t{c[2]} >> shift};
}

bool contains(const Leaf& leaf, p4est_qcoord_t x, p4est_qcoord_t y, p4est_qcoord_t z) {
    const auto lo = qcorner(leaf);
    const p4est_qcoord_t len = P8EST_QUADRANT_LEN(leaf.level);
    return x >= lo[0] && x < lo[0] + len && y >= lo[1] && y < lo[1] + len && z >= lo[2] && z < lo[2] + len;
}

// Counts to displacements.
std::vector<int> displacements(const std::vector<int>& counts) {
    std::vector<int> d(counts.size() + 1, 0);
    for (std::size_t r = 0; r < counts.size(); ++r) d[r + 1] = d[r] + counts[r];
    return d;
}

}  // namespace

std::uint64_t morton(p4est_qcoord_t x, p4est_qcoord_t y, p4est_qcoord_t z) {
    const std::uint64_t c[3] = {static_cast<std::uint64_t>(x) >> 1, static_cast<std::uint64_t>(y) >> 1,
                                static_cast<std::uint64_t>(z) >> 1};
    std::uint64_t m = 0;
    for (int b = 0; b < kBits; ++b)
        for (int a = 0; a < 3; ++a) m |= ((c[a] >> b) & 1U) << (3 * b + a);
    return m;
}

std::array<p4est_qcoord_t, 3> qcorner(const Leaf& cell) {
    const int shift = P8EST_MAXLEVEL - cell.level;
    return {static_cast<p4est_qcoord_t>(cell.i << shift), static_cast<p4est_qcoord_t>(cell.j << shift),
            static_cast<p4est_qcoord_t>(cell.k << shift)};
}

LeafIndex::LeafIndex(const std::vector<Leaf>& leaves, const std::vector<int>& ranks) {
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
    keyed.reserve(leaves.size());
    for (std::size_t n = 0; n < leaves.size(); ++n) {
        const auto c = qcorner(leaves[n]);
        keyed.emplace_back(morton(c[0], c[1], c[2]), n);
    }
    std::sort(keyed.begin(), keyed.end());
    for (const auto& [k, n] : keyed) {
        keys_.push_back(k);
        leaves_.push_back(leaves[n]);
        if (!ranks.empty()) ranks_.push_back(ranks[n]);
    }
}

const Leaf* LeafIndex::locate(p4est_qcoord_t x, p4est_qcoord_t y, p4est_qcoord_t z) const {
    // In Morton order a leaf covers the indices from its min corner's on: the candidate is
    // the last leaf starting at or before the point (checked, as ghosts leave holes).
    const auto it = std::upper_bound(keys_.begin(), keys_.end(), morton(x, y, z));
    if (it == keys_.begin()) return nullptr;
    const Leaf& leaf = leaves_[static_cast<std::size_t>(it - keys_.begin() - 1)];
    return contains(leaf, x, y, z) ? &leaf : nullptr;
}

LevelOracle::LevelOracle(p8est_t* forest, const LeafIndex& local, const LeafIndex& held, std::vector<std::uint64_t> points) {
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    stats_.points_asked = points.size();
    levels_ = CellMap<std::int8_t>(points.size() + 16);
    const int size = forest->mpisize;
    std::vector<std::vector<std::uint64_t>> ask(static_cast<std::size_t>(size));
    int guess = forest->mpirank;
    for (std::uint64_t m : points) {
        const auto c = unmorton(m);
        if (const Leaf* l = held.locate(c[0], c[1], c[2])) {
            levels_.insert(finest_cell(c), static_cast<std::int8_t>(l->level));
            continue;
        }
        p8est_quadrant_t q;
        P8EST_QUADRANT_INIT(&q);
        q.x = c[0], q.y = c[1], q.z = c[2];
        q.level = P8EST_QMAXLEVEL;
        guess = p8est_comm_find_owner(forest, 0, &q, guess);
        ask[static_cast<std::size_t>(guess)].push_back(m);
    }
    std::vector<int> send_counts(static_cast<std::size_t>(size)), recv_counts(static_cast<std::size_t>(size));
    std::vector<std::uint64_t> send;
    for (int r = 0; r < size; ++r) {
        send_counts[static_cast<std::size_t>(r)] = static_cast<int>(ask[static_cast<std::size_t>(r)].size());
        send.insert(send.end(), ask[static_cast<std::size_t>(r)].begin(), ask[static_cast<std::size_t>(r)].end());
    }
    stats_.points_remote = send.size();
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, forest->mpicomm);
    const std::vector<int> sd = displacements(send_counts), rd = displacements(recv_counts);
    std::vector<std::uint64_t> recv(static_cast<std::size_t>(rd.back()));
    MPI_Alltoallv(send.data(), send_counts.data(), sd.data(), MPI_UINT64_T, recv.data(), recv_counts.data(), rd.data(),
                  MPI_UINT64_T, forest->mpicomm);
    // Answer the points others asked: each lies in one of our leaves (we own it).
    std::vector<std::int8_t> answers(recv.size());
    for (std::size_t n = 0; n < recv.size(); ++n) {
        const auto c = unmorton(recv[n]);
        const Leaf* l = local.locate(c[0], c[1], c[2]);
        if (!l) throw std::logic_error("rank " + std::to_string(forest->mpirank) + " asked for a point it does not own");
        answers[n] = static_cast<std::int8_t>(l->level);
    }
    std::vector<std::int8_t> replies(send.size());
    MPI_Alltoallv(answers.data(), recv_counts.data(), rd.data(), MPI_INT8_T, replies.data(), send_counts.data(), sd.data(),
                  MPI_INT8_T, forest->mpicomm);
    for (std::size_t n = 0; n < send.size(); ++n) levels_.insert(finest_cell(unmorton(send[n])), replies[n]);
    stats_.bytes_sent = send.size() * sizeof(std::uint64_t) + answers.size();
    stats_.bytes_received = recv.size() * sizeof(std::uint64_t) + replies.size();
}

int LevelOracle::level_at(const Leaf& cell) const {
    const std::int8_t* level = levels_.find(finest_cell(qcorner(cell)));
    if (!level) throw std::logic_error("context query outside the gathered points: cell " + to_string(cell));
    return *level;
}

}  // namespace dualhex::dist
