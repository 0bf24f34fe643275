// The joint reads of a vertex's star near a lattice point g, relevant bits only
// (compositional_weak_stars.hpp, weak_star_reads; proofs/README.md W7).
//
// World units: a level-(m+2) cell is U (the influence table's leaf), a level-(m+1) cell 2U,
// a level-m cell 4U; g = parity (level-m units) sits at 4U * parity. A status is named by
// (level offset from m, cell index at that level).
#include <algorithm>
#include <map>
#include <set>

#include "dualhex/checkers/compositional_weak_stars.hpp"
#include "dualhex/install/element_templates.hpp"

namespace dualhex {
namespace {

using detail::Index3;
using Status = std::pair<int, Index3>;  // (level - m, cell)

constexpr int kFirst = 0, kLast = 2;  // levels m .. m+2 may carry an element at v (W5)

std::int64_t cell_size(std::int64_t unit, int level) { return unit << (kLast - level); }

Index3 parent(const Index3& c) { return {detail::floor_div(c[0], 2), detail::floor_div(c[1], 2), detail::floor_div(c[2], 2)}; }

LeafContext frame_of(const Index3& c) {
    return detail::coarse_leaf_context(LatticePoint{c[0], c[1], c[2]}, [](const Index3&) { return false; });
}

// The level-`level` cells whose closure holds the world point v.
std::vector<Index3> cells_at(const LatticePoint& v, std::int64_t size) {
    std::array<std::vector<std::int64_t>, 3> per_axis;
    for (int a = 0; a < 3; ++a) {
        const std::int64_t lo = detail::floor_div(v[a], size);
        per_axis[static_cast<std::size_t>(a)].push_back(lo);
        if (v[a] == lo * size) per_axis[static_cast<std::size_t>(a)].push_back(lo - 1);
    }
    std::vector<Index3> out;
    for (auto x : per_axis[0])
        for (auto y : per_axis[1])
            for (auto z : per_axis[2]) out.push_back({x, y, z});
    return out;
}

// v in the frame of the leaf in cell c (size S), in table units; nullopt if not integral.
std::optional<LatticePoint> local_of(const LatticePoint& v, const LeafContext& frame, std::int64_t size, std::int64_t unit) {
    LatticePoint q;
    for (int a = 0; a < 3; ++a) {
        const std::int64_t d = frame.direction[static_cast<std::size_t>(a)];
        const std::int64_t x = d * (v[a] - frame.application_point[a] * size) * unit;
        if (x % size != 0) return std::nullopt;
        q[a] = x / size;
    }
    return q;
}

// The statuses the possible leaf in cell c of level `level` reads for its piece at v.
void add_reads(const WeakStarInfluence& inf, const std::map<LatticePoint, std::size_t>& index, const LatticePoint& v,
               int level, const Index3& c, std::map<Status, int>& readers) {
    const LeafContext frame = frame_of(c);
    std::set<Status> mine{{level - 1, parent(c)}};
    if (level > kFirst) mine.insert({level - 2, parent(parent(c))});
    if (const auto q = local_of(v, frame, cell_size(inf.unit, level), inf.unit)) {
        const auto it = index.find(*q);
        const std::uint16_t relevant = it == index.end() ? 0 : inf.positions[it->second].relevant;
        for (int i = 0; i < 9; ++i)
            if ((relevant >> i) & 1U) mine.insert({level - 1, detail::world_octant(frame, inf.octant_bits[static_cast<std::size_t>(i)])});
        for (int a = 0; a < 3; ++a) {
            if (!((relevant >> (9 + a)) & 1U)) continue;
            Index3 e{};
            for (int u = 0; u < 3; ++u) {
                const int local = u == a ? 0 : -1;
                e[static_cast<std::size_t>(u)] = frame.application_point[u] +
                                                 (frame.direction[static_cast<std::size_t>(u)] > 0 ? local : -local - 1);
            }
            mine.insert({level, e});
        }
    }
    for (const Status& s : mine) ++readers[s];
}

}  // namespace

std::vector<WeakStarReads> weak_star_reads(const WeakStarInfluence& inf) {
    std::map<LatticePoint, std::size_t> index;
    for (std::size_t q = 0; q < inf.positions.size(); ++q) index[inf.positions[q].position] = q;
    const std::int64_t U = inf.unit, half = 2 * U;  // 1/2 of a level-m cell
    std::vector<WeakStarReads> out;
    for (int t = 0; t < 8; ++t) {
        WeakStarReads r;
        r.parity = {t & 1, (t >> 1) & 1, (t >> 2) & 1};
        const LatticePoint g = LatticePoint{r.parity[0], r.parity[1], r.parity[2]} * (4 * U);
        const auto near_g = [&](const LatticePoint& w) {
            for (int a = 0; a < 3; ++a)
                if (w[a] < g[a] - half || w[a] > g[a] + half) return false;
            return true;
        };
        // the candidate vertices: every element vertex of a possible leaf, within 1/2 of g
        std::set<LatticePoint> vertices;
        for (int level = kFirst; level <= kLast; ++level) {
            const std::int64_t S = cell_size(U, level);
            std::set<Index3> cells;
            for (int c = 0; c < 8; ++c) {
                const LatticePoint corner = g + LatticePoint{c & 1 ? half : -half, c & 2 ? half : -half, c & 4 ? half : -half};
                for (const Index3& cell : cells_at(corner, S)) cells.insert(cell);
            }
            for (const Index3& cell : cells) {
                const LeafContext frame = frame_of(cell);
                for (const auto& info : inf.positions) {
                    LatticePoint w;
                    for (int a = 0; a < 3; ++a)
                        w[a] = frame.application_point[a] * S + frame.direction[static_cast<std::size_t>(a)] * info.position[a] * S / U;
                    if (near_g(w)) vertices.insert(w);
                }
            }
        }
        for (const LatticePoint& v : vertices) {
            std::map<Status, int> readers;
            int leaves = 0;
            for (int level = kFirst; level <= kLast; ++level)
                for (const Index3& c : cells_at(v, cell_size(U, level))) {
                    add_reads(inf, index, v, level, c, readers);
                    ++leaves;
                }
            const int shared = static_cast<int>(std::count_if(readers.begin(), readers.end(), [](const auto& e) { return e.second > 1; }));
            ++r.vertices;
            ++r.shared_histogram[shared];
            r.max_statuses = std::max(r.max_statuses, static_cast<int>(readers.size()));
            r.max_leaves = std::max(r.max_leaves, leaves);
            if (shared > r.max_shared) r.max_shared = shared, r.worst = v - g;
        }
        out.push_back(r);
    }
    return out;
}

}  // namespace dualhex
