// Feature detection (feature_curves.hpp): dihedral classification of the edges, corners by
// feature valence and turn angle, curves by walking feature edges between corners.
#include "dualhex/geometry/feature_curves.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace dualhex::geometry {
namespace {

std::uint64_t edge_key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

double degrees_to_cos(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }

// Unit normal of each triangle; zero for a degenerate one (area below rounding of its edges).
std::vector<Eigen::Vector3d> triangle_normals(const TriangleSurface& s) {
    std::vector<Eigen::Vector3d> normals;
    normals.reserve(s.triangles.size());
    for (const auto& t : s.triangles) {
        const Eigen::Vector3d& a = s.vertices[static_cast<std::size_t>(t[0])];
        const Eigen::Vector3d e1 = s.vertices[static_cast<std::size_t>(t[1])] - a;
        const Eigen::Vector3d e2 = s.vertices[static_cast<std::size_t>(t[2])] - a;
        const Eigen::Vector3d n = e1.cross(e2);
        const double scale = e1.squaredNorm() + e2.squaredNorm();
        normals.push_back(n.norm() > 1e-12 * scale ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
    }
    return normals;
}

// A feature edge and the two triangles it separates.
struct SharpEdge {
    std::array<int, 2> edge;
    std::array<int, 2> triangles;
    bool operator<(const SharpEdge& o) const { return edge < o.edge; }
};

// Feature edges: the two triangles' normals deviate by more than the angle; `smooth`
// receives the triangle pairs across the other edges.
std::vector<SharpEdge> feature_edges(const TriangleSurface& s, double angle_degrees,
                                     std::vector<std::array<int, 2>>& smooth) {
    const std::vector<Eigen::Vector3d> normals = triangle_normals(s);
    std::unordered_map<std::uint64_t, std::array<int, 3>> uses;  // key -> count, first, second triangle
    uses.reserve(3 * s.triangles.size());
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            auto& u = uses.try_emplace(edge_key(s.triangles[t][i], s.triangles[t][(i + 1) % 3]),
                                       std::array<int, 3>{0, -1, -1}).first->second;
            if (u[0] < 2) u[1 + u[0]] = static_cast<int>(t);
            ++u[0];
        }
    const double cos_max = degrees_to_cos(angle_degrees);
    std::vector<SharpEdge> edges;
    for (const auto& [key, u] : uses) {
        const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
        if (u[0] != 2)
            throw std::invalid_argument("feature detection needs a closed manifold surface: edge " + std::to_string(a) +
                                        "-" + std::to_string(b) + " is in " + std::to_string(u[0]) + " triangles");
        const Eigen::Vector3d& n1 = normals[static_cast<std::size_t>(u[1])];
        const Eigen::Vector3d& n2 = normals[static_cast<std::size_t>(u[2])];
        if (!n1.isZero() && !n2.isZero() && n1.dot(n2) < cos_max)
            edges.push_back({{a, b}, {u[1], u[2]}});
        else
            smooth.push_back({u[1], u[2]});
    }
    std::sort(edges.begin(), edges.end());
    return edges;
}

// Drops the feature edges of every chain (connected component of feature edges, corners
// not splitting it) shorter than `min_length` in total; their triangle pairs join `smooth`.
// Why whole chains: on CAD models a short curve between two corners belongs to a long
// network of creases and is kept, while the creases of an organic model's tessellation are
// short isolated chains (cgal_armadillo: 355 chains, the longest 7.5% of the diagonal).
std::vector<SharpEdge> drop_short_chains(const TriangleSurface& s, std::vector<SharpEdge> edges, double min_length,
                                         std::vector<std::array<int, 2>>& smooth) {
    if (!(min_length > 0)) return edges;
    std::vector<int> parent(s.vertices.size());
    for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<int>(v);
    auto find = [&](int v) {
        while (parent[static_cast<std::size_t>(v)] != v)
            v = parent[static_cast<std::size_t>(v)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
        return v;
    };
    for (const SharpEdge& e : edges) parent[static_cast<std::size_t>(find(e.edge[0]))] = find(e.edge[1]);
    std::unordered_map<int, double> length;  // chain root -> total length
    for (const SharpEdge& e : edges)
        length[find(e.edge[0])] += (s.vertices[static_cast<std::size_t>(e.edge[0])] -
                                    s.vertices[static_cast<std::size_t>(e.edge[1])]).norm();
    std::vector<SharpEdge> kept;
    for (const SharpEdge& e : edges)
        if (length.at(find(e.edge[0])) >= min_length)
            kept.push_back(e);
        else
            smooth.push_back(e.triangles);
    return kept;
}

// Patch id per triangle: the components of the triangles joined across `smooth` pairs,
// numbered in order of their smallest triangle.
std::vector<int> patches(std::size_t triangles, const std::vector<std::array<int, 2>>& smooth, int& count) {
    std::vector<int> parent(triangles);
    for (std::size_t t = 0; t < triangles; ++t) parent[t] = static_cast<int>(t);
    auto find = [&](int t) {
        while (parent[static_cast<std::size_t>(t)] != t)
            t = parent[static_cast<std::size_t>(t)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(t)])];
        return t;
    };
    for (const auto& [a, b] : smooth) {
        const int ra = find(a), rb = find(b);
        parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
    std::vector<int> id(triangles, -1);
    count = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const int r = find(static_cast<int>(t));
        if (id[static_cast<std::size_t>(r)] < 0) id[static_cast<std::size_t>(r)] = count++;
        id[t] = id[static_cast<std::size_t>(r)];
    }
    return id;
}

struct FeatureGraph {
    std::vector<std::vector<int>> edges_at;  // (vertices): incident feature edge ids
    const std::vector<std::array<int, 2>>* edges = nullptr;
    [[nodiscard]] int other(int edge, int v) const {
        const auto& e = (*edges)[static_cast<std::size_t>(edge)];
        return e[0] == v ? e[1] : e[0];
    }
};

std::vector<char> corner_flags(const TriangleSurface& s, const FeatureGraph& g, double turn_degrees) {
    const double cos_turn = degrees_to_cos(turn_degrees);
    std::vector<char> corner(s.vertices.size(), 0);
    for (std::size_t v = 0; v < s.vertices.size(); ++v) {
        const auto& at = g.edges_at[v];
        if (at.empty()) continue;
        if (at.size() != 2) {
            corner[v] = 1;
            continue;
        }
        const int vi = static_cast<int>(v);
        const Eigen::Vector3d in = s.vertices[v] - s.vertices[static_cast<std::size_t>(g.other(at[0], vi))];
        const Eigen::Vector3d out = s.vertices[static_cast<std::size_t>(g.other(at[1], vi))] - s.vertices[v];
        const double norms = in.norm() * out.norm();
        corner[v] = norms > 0 && in.dot(out) < cos_turn * norms;
    }
    return corner;
}

// Walks from `start` along feature edge `edge` until a corner (or back at `start`).
FeatureCurve walk(const TriangleSurface& s, const FeatureGraph& g, const std::vector<char>& corner, int start,
                  int edge, std::vector<char>& used) {
    FeatureCurve c;
    c.vertices.push_back(start);
    int v = start;
    while (true) {
        used[static_cast<std::size_t>(edge)] = 1;
        v = g.other(edge, v);
        if (v == start && !corner[static_cast<std::size_t>(start)]) {
            c.closed = true;
            break;
        }
        c.vertices.push_back(v);
        if (corner[static_cast<std::size_t>(v)]) break;
        const auto& at = g.edges_at[static_cast<std::size_t>(v)];  // two edges: not a corner
        edge = used[static_cast<std::size_t>(at[0])] ? at[1] : at[0];
        if (used[static_cast<std::size_t>(edge)]) break;  // unreachable on a valid graph; keeps the loop finite
    }
    for (int id : c.vertices) c.points.push_back(s.vertices[static_cast<std::size_t>(id)]);
    return c;
}

}  // namespace

double FeatureCurve::length() const {
    double l = 0;
    for (std::size_t i = 1; i < points.size(); ++i) l += (points[i] - points[i - 1]).norm();
    if (closed && points.size() > 1) l += (points.front() - points.back()).norm();
    return l;
}

std::vector<std::vector<Eigen::Vector3d>> FeatureSet::polylines() const {
    std::vector<std::vector<Eigen::Vector3d>> out;
    for (const auto& c : curves) out.push_back(c.points);
    return out;
}

FeatureSet detect_features(const TriangleSurface& surface, const FeatureOptions& options) {
    if (!(options.angle_degrees > 0 && options.angle_degrees < 180))
        throw std::invalid_argument("feature angle must be in (0, 180) degrees, got " +
                                    std::to_string(options.angle_degrees));
    if (!(options.turn_degrees > 0 && options.turn_degrees < 180))
        throw std::invalid_argument("corner turn angle must be in (0, 180) degrees, got " +
                                    std::to_string(options.turn_degrees));
    if (!(options.min_chain_length >= 0))
        throw std::invalid_argument("feature chain length must be >= 0, got " + std::to_string(options.min_chain_length));
    FeatureSet out;
    std::vector<std::array<int, 2>> smooth;
    for (const SharpEdge& e : drop_short_chains(surface, feature_edges(surface, options.angle_degrees, smooth),
                                                options.min_chain_length, smooth))
        out.edges.push_back(e.edge);
    out.patch = patches(surface.triangles.size(), smooth, out.patches);
    FeatureGraph g;
    g.edges = &out.edges;
    g.edges_at.resize(surface.vertices.size());
    for (std::size_t e = 0; e < out.edges.size(); ++e)
        for (int v : out.edges[e]) g.edges_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(e));
    const std::vector<char> corner = corner_flags(surface, g, options.turn_degrees);
    for (std::size_t v = 0; v < corner.size(); ++v)
        if (corner[v]) out.corners.push_back(static_cast<int>(v));

    std::vector<char> used(out.edges.size(), 0);
    std::unordered_map<std::uint64_t, int> triangle_of;  // directed edge (a, b) -> its triangle
    for (std::size_t t = 0; t < surface.triangles.size(); ++t)
        for (int i = 0; i < 3; ++i) {
            const auto a = static_cast<std::uint32_t>(surface.triangles[t][i]);
            const auto b = static_cast<std::uint32_t>(surface.triangles[t][(i + 1) % 3]);
            triangle_of[static_cast<std::uint64_t>(a) << 32 | b] = static_cast<int>(t);
        }
    auto side = [&](int a, int b) {
        const auto it = triangle_of.find(static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 |
                                         static_cast<std::uint32_t>(b));
        return it == triangle_of.end() ? -1 : out.patch[static_cast<std::size_t>(it->second)];
    };
    for (int c : out.corners)  // open curves (and loops through one corner) start at corners
        for (int e : g.edges_at[static_cast<std::size_t>(c)])
            if (!used[static_cast<std::size_t>(e)]) out.curves.push_back(walk(surface, g, corner, c, e, used));
    for (std::size_t e = 0; e < out.edges.size(); ++e)  // what is left are closed loops
        if (!used[e]) out.curves.push_back(walk(surface, g, corner, out.edges[e][0], static_cast<int>(e), used));
    for (auto& c : out.curves) {  // counter-clockwise seen from outside: a -> b has its triangle on the left
        const int a = c.vertices[0], b = c.vertices[1];
        c.sides = {side(a, b), side(b, a)};
    }
    return out;
}

PolylinePoint closest_on_polyline(const std::vector<Eigen::Vector3d>& points, bool closed, const Eigen::Vector3d& p) {
    PolylinePoint best{points.front(), 0, (p - points.front()).norm()};
    const std::size_t segments = closed ? points.size() : points.size() - 1;
    double arc = 0;
    for (std::size_t i = 0; i < segments; ++i) {
        const Eigen::Vector3d& a = points[i];
        const Eigen::Vector3d& b = points[(i + 1) % points.size()];
        const Eigen::Vector3d ab = b - a;
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        const Eigen::Vector3d q = a + t * ab;
        const double d = (p - q).norm();
        if (d < best.distance) best = {q, arc + t * std::sqrt(len2), d};
        arc += std::sqrt(len2);
    }
    return best;
}

Eigen::Vector3d point_at_arc(const std::vector<Eigen::Vector3d>& points, bool closed, double arc) {
    const std::size_t segments = closed ? points.size() : points.size() - 1;
    for (std::size_t i = 0; i < segments; ++i) {
        const Eigen::Vector3d& a = points[i];
        const Eigen::Vector3d& b = points[(i + 1) % points.size()];
        const double len = (b - a).norm();
        if (arc <= len) return len > 0 ? Eigen::Vector3d(a + (std::max(arc, 0.0) / len) * (b - a)) : a;
        arc -= len;
    }
    return closed ? points.front() : points.back();
}

}  // namespace dualhex::geometry
