// The features stage (features.hpp): corners by a greedy unique assignment, curves by
// shortest boundary-edge paths pulled onto them.
#include "dualhex/mesher/features.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/mesher/quality_state.hpp"
#include "corner_exits.hpp"
#include "feature_path_rule.hpp"
#include "hex_edges.hpp"

namespace dualhex::mesher {
namespace {

using geometry::FeatureCurve;
using geometry::FeatureSet;
using geometry::HexMesh;
using Points = std::vector<Eigen::Vector3d>;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The boundary quads' vertices and edges as a graph (by vertex id).
struct BoundaryGraph {
    std::vector<int> vertices;             // boundary vertex ids, ascending
    std::vector<std::vector<int>> adj;     // (points): boundary-edge neighbours
    std::unordered_set<std::uint64_t> diagonals;  // edge_key of each boundary quad's two diagonals
    double mean_edge = 0;

    // Whether a path a -> (a common neighbour) -> c takes two edges of one boundary quad:
    // a and c are then its opposite corners (a quad is the only 4-cycle through a diagonal).
    [[nodiscard]] bool turns_in_quad(int a, int c) const { return diagonals.contains(detail::edge_key(a, c)); }
};

BoundaryGraph boundary_graph(const HexMesh& mesh) {
    BoundaryGraph g;
    g.adj.resize(mesh.points.size());
    std::unordered_set<std::uint64_t> seen;
    double total = 0;
    for (const auto& q : geometry::boundary_quads(mesh)) {
        g.diagonals.insert(detail::edge_key(q[0], q[2]));
        g.diagonals.insert(detail::edge_key(q[1], q[3]));
        for (int i = 0; i < 4; ++i) {
            const int a = q[static_cast<std::size_t>(i)], b = q[static_cast<std::size_t>((i + 1) % 4)];
            if (!seen.insert(detail::edge_key(a, b)).second) continue;
            g.adj[static_cast<std::size_t>(a)].push_back(b);
            g.adj[static_cast<std::size_t>(b)].push_back(a);
            total += (mesh.points[static_cast<std::size_t>(a)] - mesh.points[static_cast<std::size_t>(b)]).norm();
        }
    }
    for (std::size_t v = 0; v < g.adj.size(); ++v)
        if (!g.adj[v].empty()) g.vertices.push_back(static_cast<int>(v));
    g.mean_edge = seen.empty() ? 0 : total / static_cast<double>(seen.size());
    return g;
}

// The open polyline from arc a0 to arc a1 along `points` (open).
Points sub_polyline(const Points& points, double a0, double a1) {
    Points out{geometry::point_at_arc(points, false, a0)};
    double arc = 0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        arc += (points[i] - points[i - 1]).norm();
        if (arc > a0 && arc < a1) out.push_back(points[i]);
    }
    out.push_back(geometry::point_at_arc(points, false, a1));
    return out;
}

double polyline_length(const Points& p) {
    double l = 0;
    for (std::size_t i = 1; i < p.size(); ++i) l += (p[i] - p[i - 1]).norm();
    return l;
}

class Snapper {
public:
    Snapper(HexMesh& mesh, const FeatureSet& features, VertexConstraints& constraints,
            const FeatureSnapOptions& options)
        : mesh_(mesh), features_(features), c_(constraints), options_(options), g_(boundary_graph(mesh)) {}

    FeatureSnapReport run() {
        report_.corners = features_.corners.size();
        report_.curves = features_.curves.size();
        report_.inverted_before = count_inverted(mesh_);
        if (!g_.vertices.empty()) {
            snap_corners();
            snap_curves();
        }
        report_.inverted_after = count_inverted(mesh_);
        return report_;
    }

private:
    HexMesh& mesh_;
    const FeatureSet& features_;
    VertexConstraints& c_;
    FeatureSnapOptions options_;
    BoundaryGraph g_;
    std::unordered_set<std::uint64_t> used_edges_;
    std::unordered_map<int, int> corner_vertex_;  // input corner id -> hex vertex
    std::unordered_map<int, int> pending_;        // corner vertex -> curve ends at it not yet snapped
    std::unordered_map<int, int> exit_owner_;     // a corner's neighbour -> the curve leaving the corner by it
    FeatureSnapReport report_;

    // What the curve pass changes, to restart it.
    struct State {
        Points points;
        VertexConstraints constraints;
        std::unordered_set<std::uint64_t> used_edges;
        FeatureSnapReport report;
        std::unordered_map<int, int> pending;
    };
    [[nodiscard]] State state() const { return {mesh_.points, c_, used_edges_, report_, pending_}; }
    void restore(const State& s) {
        mesh_.points = s.points;
        c_ = s.constraints;
        used_edges_ = s.used_edges;
        report_ = s.report;
        pending_ = s.pending;
    }

    // Shortest curves first; a curve that finds no path (walled off by earlier paths) goes
    // first in the next of a few passes (rip-up and retry); the pass snapping the greatest
    // length of curve wins (what the sharp-edge samples measure); two passes without a
    // better one end the search.
    void snap_curves() {
        constexpr int kPasses = 8, kStalePasses = 2;
        std::vector<std::size_t> order(features_.curves.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::vector<double> length;
        for (const auto& curve : features_.curves) length.push_back(curve.length());
        std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return length[a] < length[b]; });
        for (const auto& curve : features_.curves)
            if (!curve.closed)
                for (int end : {curve.vertices.front(), curve.vertices.back()})
                    if (corner_vertex_.contains(end)) ++pending_[corner_vertex_.at(end)];
        assign_exits();
        const State start = state();
        State best = start;
        double best_length = -1;
        int stale = 0;  // passes since the best
        for (int pass = 0; pass < kPasses; ++pass) {
            if (pass > 0) restore(start);
            std::vector<std::size_t> failed, snapped;
            double snapped_length = 0;
            for (std::size_t i : order)
                if (snap_curve(i)) {
                    snapped.push_back(i);
                    snapped_length += length[i];
                } else {
                    failed.push_back(i);
                }
            report_.curves_snapped = snapped.size();
            if (snapped_length > best_length) {
                best = state();
                best_length = snapped_length;
                stale = 0;
            } else if (++stale == kStalePasses) {
                break;  // noisy inputs (hundreds of curves on an organic model) stop early
            }
            if (failed.empty()) break;
            order = failed;
            order.insert(order.end(), snapped.begin(), snapped.end());
        }
        restore(best);
    }

    [[nodiscard]] const Eigen::Vector3d& at(int v) const { return mesh_.points[static_cast<std::size_t>(v)]; }
    [[nodiscard]] bool is_free(int v) const {
        const VertexRole r = c_.role[static_cast<std::size_t>(v)];
        return r != VertexRole::Curve && r != VertexRole::Corner;
    }
    [[nodiscard]] double max_move() const { return options_.max_corner_move * g_.mean_edge; }

    void move(int v, const Eigen::Vector3d& p, VertexRole role, int curve) {
        report_.max_move = std::max(report_.max_move, (at(v) - p).norm());
        mesh_.points[static_cast<std::size_t>(v)] = p;
        c_.role[static_cast<std::size_t>(v)] = role;
        c_.curve[static_cast<std::size_t>(v)] = curve;
        if (role == VertexRole::Curve) ++report_.curve_vertices;
    }

    // Greedy unique assignment over each corner's 8 nearest boundary vertices, then the
    // nearest free vertex for corners left over; both within max_move().
    void snap_corners() {
        constexpr std::size_t kCandidates = 8;
        std::vector<std::tuple<double, int, int>> pairs;  // distance, corner, vertex
        for (int corner : features_.corners) {
            const Eigen::Vector3d p = corner_point(corner);
            std::vector<std::pair<double, int>> d;
            for (int v : g_.vertices) d.emplace_back((at(v) - p).norm(), v);
            const std::size_t k = std::min(kCandidates, d.size());
            std::partial_sort(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(k), d.end());
            for (std::size_t i = 0; i < k; ++i) pairs.emplace_back(d[i].first, corner, d[i].second);
        }
        std::sort(pairs.begin(), pairs.end());
        for (const auto& [d, corner, v] : pairs)
            if (d <= max_move() && !corner_vertex_.contains(corner) && is_free(v)) place_corner(corner, v);
        for (int corner : features_.corners)
            if (!corner_vertex_.contains(corner)) {
                const int v = nearest_free(corner_point(corner));
                if (v >= 0) place_corner(corner, v);
            }
    }

    void place_corner(int corner, int v) {
        move(v, corner_point(corner), VertexRole::Corner, -1);
        corner_vertex_[corner] = v;
        ++report_.corners_snapped;
    }

    // An input corner's position, read off a curve that ends there.
    [[nodiscard]] Eigen::Vector3d corner_point(int corner) const {
        for (const auto& curve : features_.curves) {
            if (curve.vertices.front() == corner) return curve.points.front();
            if (curve.vertices.back() == corner) return curve.points.back();
        }
        throw std::invalid_argument("feature corner " + std::to_string(corner) + " ends no feature curve");
    }

    // The free boundary vertex nearest to p within max_move(), or -1.
    [[nodiscard]] int nearest_free(const Eigen::Vector3d& p) const {
        int best = -1;
        double best_d = max_move();
        for (int v : g_.vertices)
            if (is_free(v) && (at(v) - p).norm() <= best_d) {
                best = v;
                best_d = (at(v) - p).norm();
            }
        return best;
    }

    // Per corner vertex, the neighbour each curve end there leaves by (corner_exits.hpp),
    // reserved for that curve: the tangent is the direction to the curve's point one edge
    // length in. Only a reservation: forcing the paths through them snapped less.
    void assign_exits() {
        std::unordered_map<int, std::vector<int>> ends;  // corner vertex -> curve * 2 + end
        for (std::size_t i = 0; i < features_.curves.size(); ++i) {
            const FeatureCurve& c = features_.curves[i];
            if (c.closed) continue;
            for (int end = 0; end < 2; ++end) {
                const auto it = corner_vertex_.find(end == 0 ? c.vertices.front() : c.vertices.back());
                if (it != corner_vertex_.end()) ends[it->second].push_back(static_cast<int>(2 * i) + end);
            }
        }
        for (const auto& [v, list] : ends) {
            const std::vector<int>& adj = g_.adj[static_cast<std::size_t>(v)];
            std::vector<Eigen::Vector3d> tangents, directions;
            for (int w : adj) directions.push_back((at(w) - at(v)).normalized());
            for (int e : list) {
                const FeatureCurve& c = features_.curves[static_cast<std::size_t>(e / 2)];
                const double l = c.length(), into = std::min(g_.mean_edge, l / 2);
                const Eigen::Vector3d p = geometry::point_at_arc(c.points, false, e % 2 == 0 ? into : l - into);
                tangents.push_back((p - at(v)).normalized());
            }
            const std::vector<int> pick = detail::assign_exits(tangents, directions);
            for (std::size_t k = 0; k < list.size(); ++k) {
                if (pick[k] < 0) continue;
                const int w = adj[static_cast<std::size_t>(pick[k])];
                if (is_free(w)) exit_owner_[w] = list[k] / 2;
            }
        }
    }
    bool snap_curve(std::size_t index) {
        const FeatureCurve& curve = features_.curves[index];
        const int id = static_cast<int>(index);
        Points line = curve.points;
        if (curve.closed) line.push_back(curve.points.front());
        const double length = polyline_length(line);
        int s = -1, t = -1;
        if (!curve.closed) {
            const auto a = corner_vertex_.find(curve.vertices.front());
            const auto b = corner_vertex_.find(curve.vertices.back());
            if (a == corner_vertex_.end() || b == corner_vertex_.end()) return false;
            s = a->second;
            t = b->second;
        } else {
            s = nearest_free(line.front());
            if (s < 0) return false;
            move(s, line.front(), VertexRole::Curve, id);
            t = s;
        }
        if (s != t) return snap_path(s, t, line, id);
        const Eigen::Vector3d mid = geometry::point_at_arc(line, false, length / 2);
        const int m = nearest_free(mid);
        if (m < 0) return false;
        move(m, mid, VertexRole::Curve, id);
        const bool first = snap_path(s, m, sub_polyline(line, 0, length / 2), id);
        return snap_path(m, t, sub_polyline(line, length / 2, length), id) && first;
    }

    // Finds a path s -> t near `line` in widening tubes and moves its inner vertices onto it.
    bool snap_path(int s, int t, const Points& line, int id) {
        const double h = g_.mean_edge;
        // the narrow tubes also keep clear of corners that still need their edges; the
        // attempts anywhere do not, so that a crowded corner can still be reached. A path
        // taking two edges of one quad puts three of its corners on the curve (a flat pad
        // hex, mesher/README.md): first without, then, if nothing else is found, with.
        struct Attempt {
            double tube;
            bool one_edge_per_quad;
        };
        for (const Attempt a : {Attempt{3 * h, true}, Attempt{12 * h, true}, Attempt{12 * h, false},
                                Attempt{kInf, true}, Attempt{kInf, false}}) {
            if (!options_.one_edge_per_quad && a.one_edge_per_quad) continue;
            const std::vector<int> path = shortest_path(s, t, line, a.tube, id, a.one_edge_per_quad);
            if (path.empty()) continue;
            for (std::size_t i = 2; i < path.size(); ++i)
                report_.quad_turns += straight_in_quad(path[i - 2], path[i - 1], path[i], line) ? 1 : 0;
            for (std::size_t i = 1; i < path.size(); ++i) {
                used_edges_.insert(detail::edge_key(path[i - 1], path[i]));
                report_.path_edges.push_back({path[i - 1], path[i], id});
            }
            for (int end : {s, t})
                if (pending_.contains(end)) --pending_[end];
            place_on_curve(path, line, id);
            return true;
        }
        return false;
    }

    // Whether entering v takes the last edges a foreign corner next to it needs for its
    // curves still to come (a valence-3 corner with 3 curves has none to spare).
    [[nodiscard]] bool starves_corner(int v, int s, int t) const {
        for (int c : g_.adj[static_cast<std::size_t>(v)]) {
            if (c == s || c == t || c_.role[static_cast<std::size_t>(c)] != VertexRole::Corner) continue;
            const auto it = pending_.find(c);
            if (it == pending_.end() || it->second <= 0) continue;
            int free_edges = 0;
            for (int w : g_.adj[static_cast<std::size_t>(c)])
                free_edges += is_free(w) && !used_edges_.contains(detail::edge_key(c, w)) ? 1 : 0;
            if (free_edges <= it->second) return true;
        }
        return false;
    }

    // Whether the path p -> u -> v takes two edges of one boundary quad where `line` runs
    // straight (feature_path_rule.hpp).
    [[nodiscard]] bool straight_in_quad(int p, int u, int v, const Points& line) const {
        return g_.turns_in_quad(p, v) && detail::straight_on_line(at(p), at(u), at(v), line);
    }

    // Whether v is reserved as another curve's exit from its corner.
    [[nodiscard]] bool reserved_for_other(int v, int curve) const {
        const auto it = exit_owner_.find(v);
        return it != exit_owner_.end() && it->second != curve;
    }

    // Dijkstra over free boundary vertices within `tube` of `line` (t always allowed; in the
    // narrow tubes neither starving a corner nor taking another curve's exit; with
    // `one_edge_per_quad` no step continuing its predecessor's quad: a rule on the path
    // found to each vertex, so a path it rules out elsewhere is only not searched); the
    // vertex ids s..t, or empty if t is unreachable.
    [[nodiscard]] std::vector<int> shortest_path(int s, int t, const Points& line, double tube, int curve,
                                                 bool one_edge_per_quad) const {
        std::unordered_map<int, double> to_line, dist;
        std::unordered_map<int, int> prev;
        auto line_distance = [&](int v) {
            const auto it = to_line.find(v);
            if (it != to_line.end()) return it->second;
            return to_line[v] = geometry::closest_on_polyline(line, false, at(v)).distance;
        };
        const double weight = options_.path_weight / std::max(g_.mean_edge, 1e-300);
        using Item = std::pair<double, int>;
        std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
        dist[s] = 0;
        queue.emplace(0, s);
        while (!queue.empty()) {
            const auto [d, u] = queue.top();
            queue.pop();
            if (u == t) break;
            if (d > dist[u]) continue;
            for (int v : g_.adj[static_cast<std::size_t>(u)]) {
                const bool narrow = tube < kInf;
                if (v != t && (!is_free(v) || line_distance(v) > tube ||
                               (narrow && (starves_corner(v, s, t) || reserved_for_other(v, curve)))))
                    continue;
                if (used_edges_.contains(detail::edge_key(u, v))) continue;
                if (one_edge_per_quad && u != s && straight_in_quad(prev.at(u), u, v, line)) continue;
                const Eigen::Vector3d midpoint = 0.5 * (at(u) + at(v));
                const double off = (line_distance(u) + line_distance(v) +
                                    2 * geometry::closest_on_polyline(line, false, midpoint).distance) / 4;
                const double nd = d + (at(u) - at(v)).norm() * (1 + weight * off);
                const auto it = dist.find(v);
                if (it != dist.end() && it->second <= nd) continue;
                dist[v] = nd;
                prev[v] = u;
                queue.emplace(nd, v);
            }
        }
        if (!prev.contains(t)) return {};
        std::vector<int> path{t};
        while (path.back() != s) path.push_back(prev.at(path.back()));
        std::reverse(path.begin(), path.end());
        return path;
    }

    // Inner path vertices onto `line`: their closest points if strictly in order along
    // it, else at the path's relative arc length (never two on one point).
    void place_on_curve(const std::vector<int>& path, const Points& line, int id) {
        const std::size_t n = path.size();
        if (n < 3) return;
        const double length = polyline_length(line);
        std::vector<double> arc(n, 0.0);
        arc[n - 1] = length;
        bool ordered = true;
        for (std::size_t i = 1; i + 1 < n; ++i) {
            arc[i] = geometry::closest_on_polyline(line, false, at(path[i])).arc;
            ordered = ordered && arc[i] > arc[i - 1];
        }
        ordered = ordered && arc[n - 1] > arc[n - 2];
        if (!ordered) {
            std::vector<double> walked(n, 0.0);
            for (std::size_t i = 1; i < n; ++i) walked[i] = walked[i - 1] + (at(path[i]) - at(path[i - 1])).norm();
            for (std::size_t i = 1; i + 1 < n; ++i) arc[i] = length * walked[i] / walked[n - 1];
        }
        for (std::size_t i = 1; i + 1 < n; ++i)
            move(path[i], geometry::point_at_arc(line, false, arc[i]), VertexRole::Curve, id);
    }
};

}  // namespace

FeatureSnapReport snap_features(HexMesh& mesh, const FeatureSet& features, VertexConstraints& constraints,
                                const FeatureSnapOptions& options) {
    if (!(options.path_weight >= 0) || !(options.max_corner_move >= 0))
        throw std::invalid_argument("feature snapping: path weight and corner move must be >= 0");
    const std::size_t n = mesh.points.size();
    if (constraints.role.empty() && constraints.curve.empty()) {
        constraints = VertexConstraints::interior(n);
        for (const auto& q : geometry::boundary_quads(mesh))
            for (int v : q) constraints.role[static_cast<std::size_t>(v)] = VertexRole::Surface;
    }
    if (constraints.role.size() != n || constraints.curve.size() != n)
        throw std::invalid_argument("feature snapping: constraints for " + std::to_string(constraints.role.size()) +
                                    " vertices, mesh has " + std::to_string(n));
    return Snapper(mesh, features, constraints, options).run();
}

}  // namespace dualhex::mesher
