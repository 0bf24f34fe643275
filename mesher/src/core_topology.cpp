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

// How hex c would meet one side: simple (a disk of faces), a handle (two opposite faces
// and nothing else), or neither.
enum class Attach { None, Simple, Handle };

// Per vertex, the hexes containing it (all of them: the complement test needs every hex).
struct HexesAt {
    std::vector<std::size_t> start;
    std::vector<int> hex;
    HexesAt(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count) : start(vertex_count + 1, 0) {
        for (const auto& c : cells)
            for (int v : c) ++start[static_cast<std::size_t>(v) + 1];
        for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
        hex.resize(start.back());
        std::vector<std::size_t> at(start.begin(), start.end() - 1);
        for (std::size_t h = 0; h < cells.size(); ++h)
            for (int v : cells[h]) hex[at[static_cast<std::size_t>(v)]++] = static_cast<int>(h);
    }
    template <class F>
    void for_each(int v, F&& f) const {
        for (std::size_t i = start[static_cast<std::size_t>(v)]; i < start[static_cast<std::size_t>(v) + 1]; ++i) f(hex[i]);
    }
};

// The bits of the corners of each face of a hex, and the edges of each face.
struct FaceBits {
    std::array<unsigned, 6> corners{}, edges{};
    FaceBits() {
        for (int f = 0; f < 6; ++f)
            for (int i = 0; i < 4; ++i) {
                const int a = kHexFaces[f][i], b = kHexFaces[f][(i + 1) % 4];
                corners[f] |= 1u << a;
                for (int e = 0; e < 12; ++e)
                    if ((kHexEdgeCorners[e][0] == a && kHexEdgeCorners[e][1] == b) ||
                        (kHexEdgeCorners[e][0] == b && kHexEdgeCorners[e][1] == a))
                        edges[f] |= 1u << e;
            }
    }
};
const FaceBits kFaceBits;

struct Grower {
    const std::vector<std::array<int, 8>>& cells;
    HexesAt hexes_at;
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

    // How c meets the hexes n != c with in[n] == side; for side 0 (the complement) a face
    // of c that no other hex has counts as met (the outside of the mesh).
    [[nodiscard]] Attach attach(int c, char side = 1) const {
        unsigned corners = 0, edges = 0, faces = 0, any_faces = 0;  // parts of c that the side touches
        for (int corner = 0; corner < 8; ++corner)
            hexes_at.for_each(cells[c][corner], [&](int n) {
                if (n == c) return;
                const unsigned s = shared_corners(c, n);
                unsigned nf = 0;
                for (int f = 0; f < 6; ++f)
                    if ((s & kFaceBits.corners[f]) == kFaceBits.corners[f]) nf |= 1u << f;
                any_faces |= nf;
                if (in[static_cast<std::size_t>(n)] != side) return;
                corners |= s;
                faces |= nf;
                for (int e = 0; e < 12; ++e) {
                    const auto& ec = kHexEdgeCorners[e];
                    if ((s >> ec[0] & 1u) && (s >> ec[1] & 1u) && is_edge_of(n, cells[c][ec[0]], cells[c][ec[1]]))
                        edges |= 1u << e;
                }
            });
        if (side == 0) {  // faces on the mesh's outside, with their corners and edges
            const unsigned open = ~any_faces & 63u;
            faces |= open;
            for (int f = 0; f < 6; ++f)
                if (open >> f & 1u) corners |= kFaceBits.corners[f], edges |= kFaceBits.edges[f];
        }
        if (faces == 0) return Attach::None;
        unsigned fc = 0, fe = 0;  // the closure of the shared faces: its corners and edges
        for (int f = 0; f < 6; ++f)
            if (faces >> f & 1u) fc |= kFaceBits.corners[f], fe |= kFaceBits.edges[f];
        if (corners != fc || edges != fe) return Attach::None;  // touches the side outside its faces
        const int chi = __builtin_popcount(fc) - __builtin_popcount(fe) + __builtin_popcount(faces);
        if (chi == 1) return Attach::Simple;
        if (chi == 2 && __builtin_popcount(faces) == 2) return Attach::Handle;  // two opposite faces
        return Attach::None;
    }

    template <class F>
    void for_each_neighbour(int c, F&& f) const {
        for (int v : cells[static_cast<std::size_t>(c)]) hexes_at.for_each(v, f);
    }
};

// The seeds: the deepest hex of each of the `parts` largest face-connected candidate parts.
std::vector<int> part_seeds(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                            const std::vector<char>& candidate, const std::vector<double>& score, std::size_t parts) {
    std::vector<std::array<int, 8>> kept;
    std::vector<int> kept_id;
    for (std::size_t h = 0; h < cells.size(); ++h)
        if (candidate[h]) {
            kept.push_back(cells[h]);
            kept_id.push_back(static_cast<int>(h));
        }
    const std::vector<int> part = hex_face_components(kept, vertex_count);
    std::vector<int> seed(std::max<std::size_t>(parts, 1), -1);
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const auto p = static_cast<std::size_t>(part[i]);
        if (p >= seed.size()) continue;
        const int h = kept_id[i];
        if (seed[p] < 0 || score[static_cast<std::size_t>(h)] > score[static_cast<std::size_t>(seed[p])]) seed[p] = h;
    }
    return seed;
}

// Fill hexes out again, shallowest first, while one meets the complement in a disk.
void peel_fill(Grower& g, const std::vector<char>& fill, const std::vector<double>& score) {
    const auto shallower = [&](int a, int b) {  // min-heap: shallowest on top, ties by index
        const double sa = score[static_cast<std::size_t>(a)], sb = score[static_cast<std::size_t>(b)];
        return sa > sb || (sa == sb && a > b);
    };
    std::priority_queue<int, std::vector<int>, decltype(shallower)> front(shallower);
    std::vector<char> queued(fill.size(), 0);
    for (std::size_t h = 0; h < fill.size(); ++h)
        if (fill[h] && g.in[h]) {
            queued[h] = 1;
            front.push(static_cast<int>(h));
        }
    while (!front.empty()) {
        const int c = front.top();
        front.pop();
        queued[static_cast<std::size_t>(c)] = 0;
        if (!g.in[static_cast<std::size_t>(c)] || g.attach(c, 0) != Attach::Simple) continue;
        g.in[static_cast<std::size_t>(c)] = 0;
        g.for_each_neighbour(c, [&](int n) {
            if (fill[static_cast<std::size_t>(n)] && g.in[static_cast<std::size_t>(n)] && !queued[static_cast<std::size_t>(n)]) {
                queued[static_cast<std::size_t>(n)] = 1;
                front.push(n);
            }
        });
    }
}

}  // namespace

std::vector<char> grow_core_with_topology(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                                          const std::vector<char>& candidate, const std::vector<double>& score,
                                          std::size_t parts, std::size_t handles) {
    return grow_core_with_topology(cells, vertex_count, candidate, {}, score, parts, handles);
}

std::vector<char> grow_core_with_topology(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count,
                                          const std::vector<char>& candidate, const std::vector<char>& fill_in,
                                          const std::vector<double>& score, std::size_t parts, std::size_t handles) {
    const std::size_t m = cells.size();
    std::vector<char> fill(m, 0);
    for (std::size_t h = 0; h < std::min(m, fill_in.size()); ++h) fill[h] = fill_in[h] && !candidate[h];
    Grower g{cells, HexesAt(cells, vertex_count), std::vector<char>(m, 0)};
    bool fill_open = false;  // fill hexes are grown once candidates and handles are done
    // Candidates before fill, then deepest first; ties by index, so the result is deterministic.
    const auto deeper = [&](int a, int b) {
        const bool ca = candidate[static_cast<std::size_t>(a)], cb = candidate[static_cast<std::size_t>(b)];
        if (ca != cb) return cb;
        const double sa = score[static_cast<std::size_t>(a)], sb = score[static_cast<std::size_t>(b)];
        return sa < sb || (sa == sb && a > b);
    };
    std::priority_queue<int, std::vector<int>, decltype(deeper)> front(deeper);
    std::vector<char> queued(m, 0);
    const auto push = [&](int n) {
        const auto i = static_cast<std::size_t>(n);
        if (g.in[i] || queued[i] || !(candidate[i] || (fill_open && fill[i]))) return;
        queued[i] = 1;
        front.push(n);
    };
    for (int s : part_seeds(cells, vertex_count, candidate, score, parts))
        if (s >= 0) {
            g.in[static_cast<std::size_t>(s)] = 1;
            g.for_each_neighbour(s, push);
        }
    // Simple hexes as long as there are any (a hex whose neighbour joins is looked at
    // again); then the deepest handle hex, if handles remain, and again; then the fill.
    for (;;) {
        while (!front.empty()) {
            const int c = front.top();
            front.pop();
            queued[static_cast<std::size_t>(c)] = 0;
            if (g.in[static_cast<std::size_t>(c)] || g.attach(c) != Attach::Simple) continue;
            g.in[static_cast<std::size_t>(c)] = 1;
            g.for_each_neighbour(c, push);
        }
        int best = -1;
        for (std::size_t c = 0; c < m && handles > 0; ++c)
            if (candidate[c] && !g.in[c] && (best < 0 || deeper(best, static_cast<int>(c))) &&
                g.attach(static_cast<int>(c)) == Attach::Handle)
                best = static_cast<int>(c);
        if (best >= 0) {
            g.in[static_cast<std::size_t>(best)] = 1;
            --handles;
            g.for_each_neighbour(best, push);
            continue;
        }
        if (fill_open || std::find(fill.begin(), fill.end(), 1) == fill.end()) break;
        fill_open = true;
        for (std::size_t h = 0; h < m; ++h)
            if (g.in[h]) g.for_each_neighbour(static_cast<int>(h), push);
    }
    if (fill_open) peel_fill(g, fill, score);
    return g.in;
}

struct SelectionFlips::Impl {
    std::vector<std::array<int, 8>> cells;  // owned: the grower refers to it
    Grower grower;
    Impl(const std::vector<std::array<int, 8>>& c, std::size_t vertex_count, std::vector<char> in)
        : cells(c), grower{cells, HexesAt(cells, vertex_count), std::move(in)} {}
};

SelectionFlips::SelectionFlips(const std::vector<std::array<int, 8>>& cells, std::size_t vertex_count, std::vector<char> in)
    : impl_(std::make_unique<Impl>(cells, vertex_count, std::move(in))) {}

SelectionFlips::~SelectionFlips() = default;

bool SelectionFlips::simple(int c) const {
    const Grower& g = impl_->grower;
    return g.attach(c, g.in[static_cast<std::size_t>(c)] ? 0 : 1) == Attach::Simple;
}

void SelectionFlips::flip(int c) {
    char& f = impl_->grower.in[static_cast<std::size_t>(c)];
    f = f ? 0 : 1;
}

const std::vector<char>& SelectionFlips::in() const { return impl_->grower.in; }

}  // namespace dualhex::mesher
