// The select-core stage (select_core.hpp).
#include "dualhex/mesher/select_core.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "dualhex/geometry/inside.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/manifold_repair.hpp"
#include "dualhex/geometry/parallel_each.hpp"
#include "dualhex/mesher/core_cleanup.hpp"
#include "dualhex/mesher/core_topology.hpp"

namespace dualhex::mesher {
namespace {

int find_root(std::vector<int>& parent, int x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
        int& p = parent[static_cast<std::size_t>(x)];
        p = parent[static_cast<std::size_t>(p)];
        x = p;
    }
    return x;
}

double mean_edge(const std::array<std::uint32_t, 8>& h, const std::vector<Eigen::Vector3d>& p) {
    double sum = 0;
    for (const auto& e : geometry::kHexEdgeCorners) sum += (p[h[e[0]]] - p[h[e[1]]]).norm();
    return sum / 12.0;
}

}  // namespace

EmbeddedDual embed_dual(const ClippedDual& dual, std::int64_t extent, const geometry::RootCube& root,
                        const geometry::AabbTree& tree) {
    const double ext = static_cast<double>(extent);
    const std::size_t n = dual.points.size();
    EmbeddedDual out;
    out.points.reserve(n);
    out.signed_distance.assign(n, 0.0);
    for (const RationalPoint& rp : dual.points)
        out.points.push_back(root.origin +
                             root.size * Eigen::Vector3d(rp.coordinate(0, ext), rp.coordinate(1, ext), rp.coordinate(2, ext)));
    std::vector<std::vector<std::uint32_t>> neighbours(n);
    for (const auto& h : dual.hexes)
        for (const auto& e : geometry::kHexEdgeCorners) {
            neighbours[h[static_cast<std::size_t>(e[0])]].push_back(h[static_cast<std::size_t>(e[1])]);
            neighbours[h[static_cast<std::size_t>(e[1])]].push_back(h[static_cast<std::size_t>(e[0])]);
        }
    // Distances, searched only up to kReach x the longest dual edge at the point: a point
    // farther from the surface is that far at least (a valid bound for the sign spreading
    // below); only inside points that far get their exact distance (the core's depth order
    // needs it; outside, every hex around is outside whatever the value).
    constexpr double kReach = 4.0;
    // Each point's search is independent (its own slots): in parallel.
    std::vector<char> capped(n, 0);
    geometry::parallel_each(n, 256, [&](std::size_t i) {
        double longest = 0;
        for (std::uint32_t q : neighbours[i]) longest = std::max(longest, (out.points[q] - out.points[i]).norm());
        const double reach = longest > 0 ? kReach * longest : INFINITY;
        const geometry::ClosestPoint c = tree.closest_point(out.points[i], reach * reach);
        capped[i] = c.triangle < 0 ? 1 : 0;
        out.signed_distance[i] = std::sqrt(c.squared_distance);
    });
    // Signs: a ray-parity test at one point per region, then spread along dual edges: if
    // |p - q| < d(p), the segment pq stays in the open ball around p that the surface does
    // not meet, so q is on p's side.
    std::vector<signed char> sign(n, 0);
    std::vector<std::uint32_t> stack;
    for (std::size_t start = 0; start < n; ++start) {
        if (sign[start] != 0) continue;
        sign[start] = geometry::is_inside(tree, out.points[start]) ? 1 : -1;
        stack.assign(1, static_cast<std::uint32_t>(start));
        while (!stack.empty()) {
            const std::uint32_t p = stack.back();
            stack.pop_back();
            for (std::uint32_t q : neighbours[p])
                if (sign[q] == 0 && (out.points[q] - out.points[p]).norm() < 0.999 * out.signed_distance[p]) {
                    sign[q] = sign[p];
                    stack.push_back(q);
                }
        }
    }
    geometry::parallel_each(n, 256, [&](std::size_t i) {
        if (capped[i] && sign[i] > 0) out.signed_distance[i] = std::sqrt(tree.squared_distance(out.points[i]));
    });
    for (std::size_t i = 0; i < n; ++i) out.signed_distance[i] *= sign[i];
    return out;
}

std::vector<int> hex_face_components(const std::vector<std::array<int, 8>>& hexes, std::size_t vertex_count) {
    (void)vertex_count;
    struct FaceUse {
        std::array<int, 4> key;
        int hex;
    };
    std::vector<FaceUse> faces;
    faces.reserve(hexes.size() * 6);
    for (std::size_t h = 0; h < hexes.size(); ++h)
        for (const auto& f : geometry::kHexFaces) {
            std::array<int, 4> k{hexes[h][f[0]], hexes[h][f[1]], hexes[h][f[2]], hexes[h][f[3]]};
            std::sort(k.begin(), k.end());
            faces.push_back({k, static_cast<int>(h)});
        }
    std::sort(faces.begin(), faces.end(), [](const FaceUse& a, const FaceUse& b) { return a.key < b.key; });
    std::vector<int> parent(hexes.size());
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t i = 1; i < faces.size(); ++i)
        if (faces[i].key == faces[i - 1].key) {
            const int a = find_root(parent, faces[i].hex), b = find_root(parent, faces[i - 1].hex);
            if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
        }
    // Roots are the smallest hex of their class; number classes by decreasing size.
    std::vector<std::size_t> size(hexes.size(), 0);
    for (std::size_t h = 0; h < hexes.size(); ++h) ++size[static_cast<std::size_t>(find_root(parent, static_cast<int>(h)))];
    std::vector<int> roots;
    for (std::size_t h = 0; h < hexes.size(); ++h)
        if (size[h] > 0 && parent[h] == static_cast<int>(h)) roots.push_back(static_cast<int>(h));
    std::stable_sort(roots.begin(), roots.end(),
                     [&](int a, int b) { return size[static_cast<std::size_t>(a)] > size[static_cast<std::size_t>(b)]; });
    std::vector<int> index_of(hexes.size(), -1);
    for (std::size_t i = 0; i < roots.size(); ++i) index_of[static_cast<std::size_t>(roots[i])] = static_cast<int>(i);
    std::vector<int> out(hexes.size());
    for (std::size_t h = 0; h < hexes.size(); ++h)
        out[h] = index_of[static_cast<std::size_t>(find_root(parent, static_cast<int>(h)))];
    return out;
}

namespace {

// The kept parts of a selection: the `keep` largest face-connected parts, renumbered.
void keep_largest_parts(const std::vector<std::array<int, 8>>& cells, const std::vector<char>& selected,
                        const EmbeddedDual& embedded, std::size_t keep, CoreSelection& out) {
    std::vector<std::array<int, 8>> kept;
    std::vector<std::uint32_t> kept_dual;
    for (std::size_t h = 0; h < cells.size(); ++h)
        if (selected[h]) {
            kept.push_back(cells[h]);
            kept_dual.push_back(static_cast<std::uint32_t>(h));
        }
    const std::vector<int> component = hex_face_components(kept, embedded.points.size());
    std::vector<std::size_t> sizes;
    for (int c : component) {
        if (static_cast<std::size_t>(c) >= sizes.size()) sizes.resize(static_cast<std::size_t>(c) + 1, 0);
        ++sizes[static_cast<std::size_t>(c)];
    }
    out.kept_components.clear();
    out.dropped_components.clear();
    for (std::size_t c = 0; c < sizes.size(); ++c) (c < keep ? out.kept_components : out.dropped_components).push_back(sizes[c]);
    out.mesh = {};
    out.dual_hex.clear();
    std::vector<int> new_id(embedded.points.size(), -1);
    for (std::size_t h = 0; h < kept.size(); ++h) {
        if (static_cast<std::size_t>(component[h]) >= keep) continue;
        std::array<int, 8> q{};
        for (std::size_t i = 0; i < 8; ++i) {
            int& id = new_id[static_cast<std::size_t>(kept[h][i])];
            if (id < 0) {
                id = static_cast<int>(out.mesh.points.size());
                out.mesh.points.push_back(embedded.points[static_cast<std::size_t>(kept[h][i])]);
            }
            q[i] = id;
        }
        out.mesh.hexes.push_back(q);
        out.dual_hex.push_back(kept_dual[h]);
    }
}

bool has_topology(const geometry::HexTopology& t, const std::vector<geometry::SurfaceComponent>& input) {
    return t.non_manifold_edges == 0 && t.non_manifold_vertices == 0 &&
           geometry::compare_topology(t.boundary_components, input).same;
}

bool has_topology(const geometry::HexMesh& mesh, const std::vector<geometry::SurfaceComponent>& input) {
    return has_topology(geometry::check_hex_topology(mesh, 0), input);
}

}  // namespace

namespace {

std::size_t count_in(const std::vector<std::uint32_t>& hexes, const std::vector<char>& flags) {
    std::size_t n = 0;
    for (std::uint32_t h : hexes) n += flags[h] ? 1 : 0;
    return n;
}

// The rule's selection had another topology than the input, or parts beyond the input's
// number: regrown by topology-controlled steps, once cutting (candidates only) and once
// through fill hexes (closing tunnels, joining parts; first, and alone if it keeps every
// rule hex); of the results with the input's
// topology (the rule's own included), the one keeping the most of the rule's hexes, then
// the fewest fill hexes, is taken.
void choose_regrowth(const std::vector<std::array<int, 8>>& cells, const std::vector<char>& rule,
                     const std::vector<double>& score, const std::vector<double>& fill_score,
                     const EmbeddedDual& embedded, const std::vector<geometry::SurfaceComponent>& input,
                     bool rule_valid, CoreSelection& out) {
    const std::size_t keep = std::max<std::size_t>(1, input.size());
    std::size_t handles = 0;
    for (const auto& c : input) handles += static_cast<std::size_t>(std::max<std::int64_t>(0, (2 - c.euler()) / 2));
    std::vector<char> fill(cells.size(), 0);
    for (std::size_t h = 0; h < cells.size(); ++h) fill[h] = !rule[h] && fill_score[h] > 0;
    const std::size_t rule_kept = out.mesh.hexes.size();
    CoreSelection best = out;
    std::size_t best_rule = rule_valid ? rule_kept : 0, best_fill = 0;
    bool found = rule_valid;
    const auto rule_total = static_cast<std::size_t>(std::count(rule.begin(), rule.end(), 1));
    for (const bool with_fill : {true, false}) {  // cutting cannot beat a fill that kept every rule hex
        if (found && best_rule == rule_total) break;
        const std::vector<char> grown = grow_core_with_topology(cells, embedded.points.size(), rule,
                                                                with_fill ? fill : std::vector<char>{}, score, keep, handles);
        CoreSelection c = out;
        keep_largest_parts(cells, grown, embedded, keep, c);
        if (c.mesh.hexes.empty() || !has_topology(c.mesh, input)) continue;
        const std::size_t from_rule = count_in(c.dual_hex, rule);
        const std::size_t from_fill = c.mesh.hexes.size() - from_rule;
        if (found && (from_rule < best_rule || (from_rule == best_rule && from_fill >= best_fill))) continue;
        c.topology_controlled = true;
        c.topology_fill = from_fill;
        c.topology_dropped = rule_kept > from_rule ? rule_kept - from_rule : 0;
        c.topology_rejoined = from_rule > rule_kept ? from_rule - rule_kept : 0;
        best = std::move(c);
        best_rule = from_rule;
        best_fill = from_fill;
        found = true;
    }
    if (found) out = std::move(best);
}

// Per dual hex what the stage did: Thin/Outside as the rule found it, then the repair,
// the part filter (rule_core: the kept parts of the repaired selection) and the regrowth.
void set_fates(const std::vector<char>& rule, const std::vector<char>& selected, const std::vector<char>& rule_core,
               CoreSelection& out) {
    std::vector<char> in_core(rule.size(), 0);
    for (std::uint32_t h : out.dual_hex) in_core[h] = 1;
    for (std::size_t h = 0; h < rule.size(); ++h) {
        if (in_core[h]) out.fate[h] = rule[h] ? CoreFate::Core : CoreFate::FillCore;
        else if (rule_core[h]) out.fate[h] = CoreFate::Cut;
        else if (rule[h]) out.fate[h] = CoreFate::DroppedPart;
        else if (selected[h]) out.fate[h] = CoreFate::RepairOut;
    }
}

}  // namespace

const char* core_fate_name(CoreFate fate) {
    switch (fate) {
    case CoreFate::Outside: return "outside";
    case CoreFate::Thin: return "thin";
    case CoreFate::RepairOut: return "repair_removed";
    case CoreFate::DroppedPart: return "dropped_part";
    case CoreFate::Cut: return "cut";
    case CoreFate::Core: return "core";
    case CoreFate::FillCore: return "fill";
    case CoreFate::CleanedOut: return "cleanup_removed";
    case CoreFate::CleanedIn: return "cleanup_added";
    }
    return "?";
}

CoreSelection select_core(const ClippedDual& dual, const EmbeddedDual& embedded, std::size_t input_components,
                          const CoreOptions& options) {
    return select_core(dual, embedded, std::vector<geometry::SurfaceComponent>(input_components), options, false);
}

namespace {

// The dual's hexes as int cells, and per hex its least corner signed distance and mean edge.
struct DualCells {
    std::vector<std::array<int, 8>> cells;
    std::vector<double> depth, top, edge;  // least and largest corner signed distance, mean edge
};

DualCells dual_cells(const ClippedDual& dual, const EmbeddedDual& embedded) {
    DualCells d;
    for (const auto& hex : dual.hexes) {
        std::array<int, 8> c{};
        double depth = INFINITY, top = -INFINITY;
        for (std::size_t i = 0; i < 8; ++i) {
            c[i] = static_cast<int>(hex[i]);
            depth = std::min(depth, embedded.signed_distance[hex[i]]);
            top = std::max(top, embedded.signed_distance[hex[i]]);
        }
        d.cells.push_back(c);
        d.depth.push_back(depth);
        d.top.push_back(top);
        d.edge.push_back(mean_edge(hex, embedded.points));
    }
    return d;
}

bool same_boundary(const geometry::HexTopology& a, const geometry::HexTopology& b) {
    if (a.non_manifold_edges < b.non_manifold_edges || a.non_manifold_vertices < b.non_manifold_vertices) return false;
    const auto eulers = [](const geometry::HexTopology& t) {  // components by face count: their order may change
        std::vector<std::int64_t> e;
        for (const auto& c : t.boundary_components) e.push_back(c.euler());
        std::sort(e.begin(), e.end());
        return e;
    };
    return a.hex_components == b.hex_components && eulers(a) == eulers(b);
}

}  // namespace

void clean_core_selection(const ClippedDual& dual, const EmbeddedDual& embedded, const CoreOptions& options,
                          CoreSelection& core) {
    if (core.mesh.hexes.empty()) return;
    const DualCells d = dual_cells(dual, embedded);
    const std::size_t m = d.cells.size();
    std::vector<char> in(m, 0), flippable(m, 0);
    for (std::uint32_t h : core.dual_hex) in[h] = 1;
    for (std::size_t h = 0; h < m; ++h)
        flippable[h] = in[h] ? d.top[h] < options.cleanup_remove_depth * d.edge[h]
                             : d.depth[h] - options.cleanup_margin * d.edge[h] > 0;
    const CoreCleanup cleaned = clean_core(d.cells, embedded.points.size(), in, flippable);
    core.cleanup_removed = cleaned.removed;
    core.cleanup_added = cleaned.added;
    core.cleanup_refused = cleaned.refused;
    core.cleanup_sweeps = cleaned.sweeps;
    if (cleaned.removed + cleaned.added == 0) return;
    CoreSelection next = core;
    keep_largest_parts(d.cells, cleaned.in, embedded, std::max<std::size_t>(1, core.kept_components.size()), next);
    if (!same_boundary(geometry::check_hex_topology(core.mesh, 0), geometry::check_hex_topology(next.mesh, 0))) {
        core.cleanup_reverted = true;
        return;
    }
    next.dropped_components = core.dropped_components;
    for (std::size_t h = 0; h < m; ++h)
        if (in[h] != cleaned.in[h]) next.fate[h] = in[h] ? CoreFate::CleanedOut : CoreFate::CleanedIn;
    core = std::move(next);
}

CoreSelection select_core(const ClippedDual& dual, const EmbeddedDual& embedded,
                          const std::vector<geometry::SurfaceComponent>& input, const CoreOptions& options,
                          bool control_topology) {
    CoreSelection out;
    const std::size_t m = dual.hexes.size();
    std::vector<std::array<int, 8>> cells(m);
    std::vector<double> score(m), fill_score(m);
    std::vector<char> selected(m, 0);
    out.fate.assign(m, CoreFate::Outside);
    out.dual_centroid.assign(m, Eigen::Vector3d::Zero());
    for (std::size_t h = 0; h < m; ++h) {
        const auto& hex = dual.hexes[h];
        const double edge = mean_edge(hex, embedded.points);
        double depth = INFINITY;  // the least signed distance of a corner
        for (int c = 0; c < 8; ++c) {
            cells[h][static_cast<std::size_t>(c)] = static_cast<int>(hex[static_cast<std::size_t>(c)]);
            depth = std::min(depth, embedded.signed_distance[hex[static_cast<std::size_t>(c)]]);
            out.dual_centroid[h] += embedded.points[hex[static_cast<std::size_t>(c)]] / 8.0;
        }
        score[h] = depth - options.margin * edge;
        fill_score[h] = options.fill_margin < 0 ? -INFINITY : depth - options.fill_margin * edge;
        selected[h] = score[h] > 0 ? 1 : 0;
        out.selected_by_rule += static_cast<std::size_t>(selected[h]);
        out.fate[h] = depth > 0 ? CoreFate::Thin : CoreFate::Outside;
    }
    const geometry::ManifoldRepairResult repair =
        geometry::repair_manifold_selection(cells, dual.points.size(), selected, score);
    for (const auto& c : repair.changes) (c.selected ? out.repair_added : out.repair_removed) += 1;
    out.repair_manifold = repair.manifold();
    out.repair_remaining_defects = repair.remaining.non_manifold_edges.size() + repair.remaining.non_manifold_vertices.size();
    const std::size_t keep = std::max<std::size_t>(1, input.size());
    keep_largest_parts(cells, repair.selected, embedded, keep, out);
    const std::vector<char>& rule = repair.selected;
    std::vector<char> rule_core(m, 0);
    for (std::uint32_t h : out.dual_hex) rule_core[h] = 1;
    if (control_topology && !out.mesh.hexes.empty()) {
        const geometry::HexTopology t = geometry::check_hex_topology(out.mesh, 0);
        for (const auto& c : t.boundary_components) out.rule_euler.push_back(c.euler());
        const bool rule_valid = has_topology(t, input);
        if (!(rule_valid && out.dropped_components.empty()))
            choose_regrowth(cells, rule, score, fill_score, embedded, input, rule_valid, out);
    }
    set_fates(rule, selected, rule_core, out);
    return out;
}

}  // namespace dualhex::mesher
