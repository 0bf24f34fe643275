// Topology-controlled core growth (core_topology.hpp).
#include "dualhex/mesher/core_topology.hpp"

#include <algorithm>
#include <cstdint>
#include <queue>

#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/mesher/select_core.hpp"

namespace dualhex::mesher {
namespace {

using geometry::kHexEdgeCorners;
using geometry::kHexFaces;

// How hex c would meet the set: simple (a disk of faces), a handle (two opposite faces
// and nothing else), or neither.
enum class Attach { None, Simple, Handle };

struct Grower {
    const std::vector<std::array<int, 8>>& cells;
    std::vector<std::vector<int>> hexes_at;  // vertex -> candidate hexes containing it
    std::vector<char> in;

    // Bit i of the result: corner i of c is a corner of hex n.
    [[nodiscard]] unsigned shared_corners(int c, int n) const {
        unsigned bits = 0;
        for (int i = 0; i < 8; ++i)
            if (std::find(cells[n].begin(), cells[n].end(), cells[c][i]) != cells[n].end()) bits |= 1u << i;
        return bits;
    }

    [[nodiscard]] bool is_edge_of(int n, int a, int b) const {
        for (const auto& e : kHexEdgeCorners) {
            const int p = cells[n][e[0]], q = cells[n][e[1]];
            if ((p == a && q == b) || (p == b && q == a)) return true;
        }
        return false;
    }

    [[nodiscard]] Attach attach(int c) const {
        unsigned corners = 0, edges = 0, faces = 0;  // parts of c that the set touches
        for (int corner = 0; corner < 8; ++corner)
            for (int n : hexes_at[static_cast<std::size_t>(cells[c][corner])]) {
                if (n == c || !in[static_cast<std::size_t>(n)]) continue;
                const unsigned s = shared_corners(c, n);
                corners |= s;
                for (int e = 0; e < 12; ++e) {
                    const auto& ec = kHexEdgeCorners[e];
                    if ((s >> ec[0] & 1u) && (s >> ec[1] & 1u) && is_edge_of(n, cells[c][ec[0]], cells[c][ec[1]]))
                        edges |= 1u << e;
                }
                for (int f = 0; f < 6; ++f) {
                    unsigned fb = 0;
                    for (int k : kHexFaces[f]) fb |= 1u << k;
                    if ((s & fb) == fb) faces |= 1u << f;
                }
            }
        if (faces == 0) return Attach::None;
        // The closure of the shared faces: its corners and edges.
        unsigned fc = 0, fe = 0;
        for (int f = 0; f < 6; ++f) {
            if (!(faces >> f & 1u)) continue;
            const auto& q = kHexFaces[f];
            for (int i = 0; i < 4; ++i) {
                fc |= 1u << q[i];
                for (int e = 0; e < 12; ++e) {
                    const auto& ec = kHexEdgeCorners[e];
                    const int a = q[i], b = q[(i + 1) % 4];
                    if ((ec[0] == a && ec[1] == b) || (ec[0] == b && ec[1] == a)) fe |= 1u << e;
                }
            }
        }
        if (corners != fc || edges != fe) return Attach::None;  // touches S outside its faces
        const int chi = __builtin_popcount(fc) - __builtin_popcount(fe) + __builtin_popcount(faces);
        if (chi == 1) return Attach::Simple;
        if (chi == 2 && __builtin_popcount(faces) == 2) return Attach::Handle;  // two opposite faces
        return Attach::None;
    }
};

}  // namespace

std::vector<char> grow_core_with_topology(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                                          const std::vector<char>& candidate, const std::vector<double>& score,
                                          std::size_t parts, std::size_t handles) {
    const std::size_t m = cells.size();
    Grower g{cells, std::vector<std::vector<int>>(vertex_count), std::vector<char>(m, 0)};
    std::vector<std::array<int, 8>> kept;
    std::vector<int> kept_id;
    for (std::size_t h = 0; h < m; ++h)
        if (candidate[h]) {
            for (int v : cells[h]) g.hexes_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(h));
            kept.push_back(cells[h]);
            kept_id.push_back(static_cast<int>(h));
        }
    // One seed per part: the deepest hex of each of the `parts` largest face-connected parts.
    const std::vector<int> part = hex_face_components(kept, vertex_count);
    std::vector<int> seed(std::max<std::size_t>(parts, 1), -1);
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const auto p = static_cast<std::size_t>(part[i]);
        if (p >= seed.size()) continue;
        const int h = kept_id[i];
        if (seed[p] < 0 || score[static_cast<std::size_t>(h)] > score[static_cast<std::size_t>(seed[p])]) seed[p] = h;
    }
    // Deepest first; ties by index, so the result is deterministic.
    const auto deeper = [&](int a, int b) {
        const double sa = score[static_cast<std::size_t>(a)], sb = score[static_cast<std::size_t>(b)];
        return sa < sb || (sa == sb && a > b);
    };
    std::priority_queue<int, std::vector<int>, decltype(deeper)> front(deeper);
    std::vector<char> queued(m, 0);
    const auto push_neighbours = [&](int c) {
        for (int v : cells[static_cast<std::size_t>(c)])
            for (int n : g.hexes_at[static_cast<std::size_t>(v)])
                if (!g.in[static_cast<std::size_t>(n)] && !queued[static_cast<std::size_t>(n)]) {
                    queued[static_cast<std::size_t>(n)] = 1;
                    front.push(n);
                }
    };
    for (int s : seed)
        if (s >= 0) {
            g.in[static_cast<std::size_t>(s)] = 1;
            push_neighbours(s);
        }
    // Simple hexes as long as there are any (a hex whose neighbour joins is looked at
    // again); then the deepest handle hex, if handles remain, and again.
    for (;;) {
        while (!front.empty()) {
            const int c = front.top();
            front.pop();
            queued[static_cast<std::size_t>(c)] = 0;
            if (g.in[static_cast<std::size_t>(c)] || g.attach(c) != Attach::Simple) continue;
            g.in[static_cast<std::size_t>(c)] = 1;
            push_neighbours(c);
        }
        if (handles == 0) break;
        int best = -1;
        for (int c : kept_id)
            if (!g.in[static_cast<std::size_t>(c)] && (best < 0 || deeper(best, c)) && g.attach(c) == Attach::Handle)
                best = c;
        if (best < 0) break;
        g.in[static_cast<std::size_t>(best)] = 1;
        --handles;
        push_neighbours(best);
    }
    return g.in;
}

}  // namespace dualhex::mesher
