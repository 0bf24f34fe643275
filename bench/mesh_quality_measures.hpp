#pragma once
// mesh_quality: independent measures of a hex grid (own code, not the geometry layer's):
// scaled Jacobian, boundary quads, boundary edge/vertex manifoldness, face-connected
// components, Euler characteristic V - E + F of the boundary, interior edge valences.
//
// Corners are named by their (x, y, z) bits on the reference cube; VTK order lists them
// as 000 100 110 010 001 101 111 011. A corner's neighbour along an axis flips that bit.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <vector>

#include "mesh_quality_vtk.hpp"

namespace mesh_quality {

inline constexpr std::array<int, 8> kBitsOfVtkCorner{0b000, 0b001, 0b011, 0b010, 0b100, 0b101, 0b111, 0b110};

inline int vtk_corner_of_bits(int bits) {
    for (int c = 0; c < 8; ++c)
        if (kBitsOfVtkCorner[static_cast<std::size_t>(c)] == bits) return c;
    return -1;
}

// min over corners of det(ex, ey, ez) / (|ex| |ey| |ez|), e_a the edge towards +a.
inline double scaled_jacobian(const HexGrid& g, const std::array<std::int64_t, 8>& h) {
    double worst = 1e300;
    for (int c = 0; c < 8; ++c) {
        const int bits = kBitsOfVtkCorner[static_cast<std::size_t>(c)];
        const Vec3& p = g.points[static_cast<std::size_t>(h[static_cast<std::size_t>(c)])];
        double e[3][3];
        double length_product = 1;
        for (int axis = 0; axis < 3; ++axis) {
            const int n = vtk_corner_of_bits(bits ^ (1 << axis));
            const Vec3& q = g.points[static_cast<std::size_t>(h[static_cast<std::size_t>(n)])];
            const double sign = (bits >> axis & 1) ? -1.0 : 1.0;
            e[axis][0] = sign * (q.x - p.x);
            e[axis][1] = sign * (q.y - p.y);
            e[axis][2] = sign * (q.z - p.z);
            length_product *= std::sqrt(e[axis][0] * e[axis][0] + e[axis][1] * e[axis][1] + e[axis][2] * e[axis][2]);
        }
        if (!(length_product > 0)) return 0.0;
        const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        worst = std::min(worst, det / length_product);
    }
    return worst;
}

// The 4 corners (VTK indices, cyclic) of the face where bit `axis` equals `side`.
inline std::array<int, 4> face_corners(int axis, int side) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::array<int, 4> out{};
    const int walk[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i)
        out[static_cast<std::size_t>(i)] = vtk_corner_of_bits(side << axis | walk[i][0] << u | walk[i][1] << v);
    return out;
}

struct Dsu {
    std::vector<std::size_t> up;
    explicit Dsu(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), std::size_t{0}); }
    std::size_t root(std::size_t x) {
        while (up[x] != x) x = up[x] = up[up[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) { up[root(a)] = root(b); }
};

using Quad = std::array<std::int64_t, 4>;
using Edge = std::pair<std::int64_t, std::int64_t>;
inline Edge edge_of(std::int64_t a, std::int64_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

struct Topology {
    std::vector<Quad> boundary;  // quads of faces in exactly one hex (cyclic corner order)
    std::size_t non_manifold_edges = 0, non_manifold_vertices = 0;
    std::size_t components = 0;                    // face-connected hex classes
    std::size_t boundary_components = 0;           // vertex-connected boundary quad classes
    std::int64_t boundary_euler = 0;               // V - E + F of all boundary quads
    std::map<int, std::size_t> interior_valences;  // hexes at an interior edge -> edges
};

inline Topology measure_topology(const HexGrid& g) {
    Topology t;
    std::map<Quad, std::vector<std::size_t>> faces;  // sorted ids -> hexes
    std::map<Quad, Quad> cyclic;
    for (std::size_t h = 0; h < g.hexes.size(); ++h)
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                Quad q{};
                const auto fc = face_corners(axis, side);
                for (int i = 0; i < 4; ++i)
                    q[static_cast<std::size_t>(i)] =
                        g.hexes[h][static_cast<std::size_t>(fc[static_cast<std::size_t>(i)])];
                Quad key = q;
                std::sort(key.begin(), key.end());
                faces[key].push_back(h);
                cyclic.emplace(key, q);
            }
    Dsu hexes(g.hexes.size());
    for (const auto& [key, users] : faces) {
        if (users.size() == 1) t.boundary.push_back(cyclic[key]);
        for (std::size_t u = 1; u < users.size(); ++u) hexes.join(users[0], users[u]);
    }
    for (std::size_t h = 0; h < g.hexes.size(); ++h) t.components += hexes.root(h) == h;

    std::map<Edge, int> quads_at_edge;
    std::map<std::int64_t, std::vector<std::size_t>> quads_at_vertex;
    for (std::size_t q = 0; q < t.boundary.size(); ++q)
        for (int i = 0; i < 4; ++i) {
            ++quads_at_edge[edge_of(t.boundary[q][static_cast<std::size_t>(i)],
                                    t.boundary[q][static_cast<std::size_t>((i + 1) % 4)])];
            quads_at_vertex[t.boundary[q][static_cast<std::size_t>(i)]].push_back(q);
        }
    for (const auto& [e, n] : quads_at_edge) t.non_manifold_edges += n != 2;
    // A vertex is manifold iff its quads, joined across their shared edges at it, form one
    // fan and each edge at it is in exactly two of them.
    for (const auto& [v, qs] : quads_at_vertex) {
        Dsu fan(qs.size());
        std::map<std::int64_t, std::vector<std::size_t>> by_other_end;
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const Quad& q = t.boundary[qs[i]];
            for (int k = 0; k < 4; ++k)
                if (q[static_cast<std::size_t>(k)] == v) {
                    by_other_end[q[static_cast<std::size_t>((k + 1) % 4)]].push_back(i);
                    by_other_end[q[static_cast<std::size_t>((k + 3) % 4)]].push_back(i);
                }
        }
        bool ok = true;
        for (const auto& [u, users] : by_other_end) {
            ok = ok && users.size() == 2;
            for (std::size_t k = 1; k < users.size(); ++k) fan.join(users[0], users[k]);
        }
        std::size_t fans = 0;
        for (std::size_t i = 0; i < qs.size(); ++i) fans += fan.root(i) == i;
        t.non_manifold_vertices += !(ok && fans == 1);
    }
    Dsu pieces(g.points.size());
    for (const auto& q : t.boundary)
        for (int i = 1; i < 4; ++i)
            pieces.join(static_cast<std::size_t>(q[0]), static_cast<std::size_t>(q[static_cast<std::size_t>(i)]));
    for (const auto& [v, qs] : quads_at_vertex)
        t.boundary_components += pieces.root(static_cast<std::size_t>(v)) == static_cast<std::size_t>(v);
    t.boundary_euler = static_cast<std::int64_t>(quads_at_vertex.size()) -
                       static_cast<std::int64_t>(quads_at_edge.size()) + static_cast<std::int64_t>(t.boundary.size());

    std::map<Edge, int> hexes_at_edge;
    for (const auto& h : g.hexes)
        for (int c = 0; c < 8; ++c)
            for (int axis = 0; axis < 3; ++axis) {
                const int bits = kBitsOfVtkCorner[static_cast<std::size_t>(c)];
                if (bits >> axis & 1) continue;  // each edge once, from its lower corner
                const int n = vtk_corner_of_bits(bits | 1 << axis);
                ++hexes_at_edge[edge_of(h[static_cast<std::size_t>(c)], h[static_cast<std::size_t>(n)])];
            }
    for (const auto& [e, n] : hexes_at_edge)
        if (!quads_at_edge.contains(e)) ++t.interior_valences[n];
    return t;
}

}  // namespace mesh_quality
