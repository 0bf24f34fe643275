// Exact topology checks of an all-hex mesh (hex_topology.hpp).
#include "dualhex/geometry/hex_topology.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "dualhex/geometry/quality.hpp"
#include "dualhex/geometry/union_find.hpp"

namespace dualhex::geometry {
namespace {

// A face use: its canonical key (smallest id first, then the smaller neighbour second),
// whether the hex traverses it against the key's direction, and where it came from.
struct FaceUse {
    std::array<int, 4> key;
    bool reversed;
    std::size_t hex;
    int face;
    bool operator<(const FaceUse& o) const { return std::tie(key, hex, face) < std::tie(o.key, o.hex, o.face); }
};

FaceUse face_use(const std::array<int, 4>& q, std::size_t hex, int face) {
    const auto first = std::min_element(q.begin(), q.end()) - q.begin();
    std::array<int, 4> k{};
    for (int i = 0; i < 4; ++i) k[i] = q[(first + i) % 4];
    const bool reversed = k[1] > k[3];
    if (reversed) std::swap(k[1], k[3]);
    return {k, reversed, hex, face};
}

std::uint64_t edge_key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

void check_ids(const std::vector<std::array<int, 8>>& hexes, std::size_t vertex_count) {
    for (std::size_t h = 0; h < hexes.size(); ++h)
        for (int c = 0; c < 8; ++c)
            if (hexes[h][c] < 0 || static_cast<std::size_t>(hexes[h][c]) >= vertex_count)
                throw std::invalid_argument("hex " + std::to_string(h) + " corner " + std::to_string(c) +
                                            ": vertex id " + std::to_string(hexes[h][c]) + " not in [0, " +
                                            std::to_string(vertex_count) + ")");
}

std::vector<FaceUse> sorted_face_uses(const std::vector<std::array<int, 8>>& hexes) {
    std::vector<FaceUse> uses;
    uses.reserve(hexes.size() * 6);
    for (std::size_t h = 0; h < hexes.size(); ++h)
        for (int f = 0; f < 6; ++f) {
            std::array<int, 4> q{};
            for (int i = 0; i < 4; ++i) q[i] = hexes[h][kHexFaces[f][i]];
            uses.push_back(face_use(q, h, f));
        }
    std::sort(uses.begin(), uses.end());
    return uses;
}

// Calls visit(first, last) for each run of equal keys in sorted uses.
template <class Visit>
void for_each_face(const std::vector<FaceUse>& uses, Visit&& visit) {
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i + 1;
        while (j < uses.size() && uses[j].key == uses[i].key) ++j;
        visit(i, j);
        i = j;
    }
}

void check_boundary_edges(BoundaryDefects& out) {
    std::vector<std::pair<std::uint64_t, int>> directed;  // (key, +1 if walked low -> high)
    directed.reserve(out.quads.size() * 4);
    for (const auto& q : out.quads)
        for (int i = 0; i < 4; ++i)
            directed.emplace_back(edge_key(q[i], q[(i + 1) % 4]), q[i] < q[(i + 1) % 4] ? 1 : -1);
    std::sort(directed.begin(), directed.end());
    for (std::size_t i = 0; i < directed.size();) {
        std::size_t j = i;
        int direction = 0;
        while (j < directed.size() && directed[j].first == directed[i].first) direction += directed[j++].second;
        const int a = static_cast<int>(directed[i].first >> 32), b = static_cast<int>(directed[i].first & 0xffffffffu);
        const int n = static_cast<int>(j - i);
        ++out.boundary_edges;
        if (n != 2)
            out.non_manifold_edges.push_back({a, b, n});
        else if (direction != 0)
            out.misoriented_edges.push_back({a, b});
        i = j;
    }
}

// Is the link of a vertex (one arc between the two quad neighbours per quad corner at
// it) one simple cycle: connected, every link vertex of degree 2, no loop?
bool link_is_one_cycle(const std::vector<std::array<int, 2>>& arcs) {
    std::vector<int> nodes;
    for (const auto& a : arcs) nodes.insert(nodes.end(), a.begin(), a.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const auto index = [&](int v) {
        return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), v) - nodes.begin());
    };
    UnionFind uf(nodes.size());
    std::vector<int> degree(nodes.size(), 0);
    for (const auto& a : arcs) {
        if (a[0] == a[1]) return false;  // a degenerate quad
        ++degree[index(a[0])];
        ++degree[index(a[1])];
        uf.unite(index(a[0]), index(a[1]));
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (degree[i] != 2 || uf.find(i) != 0) return false;
    return true;
}

void check_boundary_vertices(BoundaryDefects& out) {
    std::vector<std::tuple<int, int, int>> corners;  // (vertex, previous, next) per quad corner
    corners.reserve(out.quads.size() * 4);
    for (const auto& q : out.quads)
        for (int i = 0; i < 4; ++i) corners.emplace_back(q[i], q[(i + 3) % 4], q[(i + 1) % 4]);
    std::sort(corners.begin(), corners.end());
    std::vector<std::array<int, 2>> arcs;
    for (std::size_t i = 0; i < corners.size();) {
        const int v = std::get<0>(corners[i]);
        arcs.clear();
        for (; i < corners.size() && std::get<0>(corners[i]) == v; ++i)
            arcs.push_back({std::get<1>(corners[i]), std::get<2>(corners[i])});
        ++out.boundary_vertices;
        if (!link_is_one_cycle(arcs)) out.non_manifold_vertices.push_back(v);
    }
}

}  // namespace

BoundaryDefects boundary_defects(const std::vector<std::array<int, 8>>& hexes, std::size_t vertex_count) {
    check_ids(hexes, vertex_count);
    BoundaryDefects out;
    for (std::size_t h = 0; h < hexes.size(); ++h) {
        auto ids = hexes[h];
        std::sort(ids.begin(), ids.end());
        if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) out.degenerate_hexes.push_back(h);
    }
    const auto uses = sorted_face_uses(hexes);
    for_each_face(uses, [&](std::size_t i, std::size_t j) {
        const auto& u = uses[i];
        std::array<int, 4> q{};
        for (int c = 0; c < 4; ++c) q[c] = hexes[u.hex][kHexFaces[u.face][c]];
        if (j - i == 1)
            out.quads.push_back(q);
        else if (j - i > 2 || uses[i].reversed == uses[i + 1].reversed)
            out.face_defects.push_back({q, static_cast<int>(j - i)});
    });
    check_boundary_edges(out);
    check_boundary_vertices(out);
    return out;
}

namespace {

// Face-connected classes of hexes: sizes, decreasing.
std::vector<std::size_t> hex_component_sizes(const std::vector<std::array<int, 8>>& hexes) {
    UnionFind uf(hexes.size());
    const auto uses = sorted_face_uses(hexes);
    for_each_face(uses, [&](std::size_t i, std::size_t j) {
        for (std::size_t k = i + 1; k < j; ++k) uf.unite(uses[i].hex, uses[k].hex);
    });
    std::vector<std::size_t> size(hexes.size(), 0);
    for (std::size_t h = 0; h < hexes.size(); ++h) ++size[uf.find(h)];
    std::erase(size, std::size_t{0});
    std::sort(size.rbegin(), size.rend());
    return size;
}

// Classes of polygons (3 or 4 corners) under "share a vertex", with V, E, F each.
template <std::size_t K>
std::vector<SurfaceComponent> polygon_components(const std::vector<std::array<int, K>>& polygons,
                                                 std::size_t vertex_count) {
    UnionFind uf(vertex_count);
    for (const auto& p : polygons)
        for (std::size_t i = 1; i < K; ++i) uf.unite(static_cast<std::size_t>(p[0]), static_cast<std::size_t>(p[i]));
    std::vector<std::uint64_t> edges;
    std::vector<char> used(vertex_count, 0);
    std::vector<SurfaceComponent> by_root(vertex_count);
    for (const auto& p : polygons) {
        ++by_root[uf.find(static_cast<std::size_t>(p[0]))].faces;
        for (std::size_t i = 0; i < K; ++i) {
            edges.push_back(edge_key(p[i], p[(i + 1) % K]));
            used[static_cast<std::size_t>(p[i])] = 1;
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (auto e : edges) ++by_root[uf.find(static_cast<std::size_t>(e >> 32))].edges;
    for (std::size_t v = 0; v < vertex_count; ++v)
        if (used[v]) ++by_root[uf.find(v)].vertices;
    std::vector<SurfaceComponent> out;
    for (const auto& c : by_root)
        if (c.faces > 0) out.push_back(c);
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.faces > b.faces; });
    return out;
}

DefectLocation locate(const HexMesh& mesh, std::vector<int> vertices, int count) {
    DefectLocation d;
    for (int v : vertices) d.points.push_back(mesh.points[static_cast<std::size_t>(v)]);
    d.vertices = std::move(vertices);
    d.count = count;
    return d;
}

std::string point_text(const Eigen::Vector3d& p) {
    std::ostringstream s;
    s << '(' << p.x() << ' ' << p.y() << ' ' << p.z() << ')';
    return s.str();
}

}  // namespace

std::string DefectLocation::describe() const {
    std::ostringstream s;
    s << (vertices.size() == 1 ? "vertex " : "vertices ");
    for (std::size_t i = 0; i < vertices.size(); ++i) s << (i ? "-" : "") << vertices[i];
    if (!points.empty()) s << " at ";
    for (std::size_t i = 0; i < points.size(); ++i) s << (i ? "-" : "") << point_text(points[i]);
    if (count > 0) s << " (" << count << ")";
    return s.str();
}

HexTopology check_hex_topology(const HexMesh& mesh, std::size_t max_listed) {
    const BoundaryDefects b = boundary_defects(mesh.hexes, mesh.points.size());
    HexTopology t;
    t.hexes = mesh.hexes.size();
    t.boundary_quads = b.quads.size();
    t.boundary_edges = b.boundary_edges;
    t.boundary_vertices = b.boundary_vertices;
    t.non_manifold_edges = b.non_manifold_edges.size();
    t.misoriented_edges = b.misoriented_edges.size();
    t.non_manifold_vertices = b.non_manifold_vertices.size();
    t.face_defects = b.face_defects.size();
    t.degenerate_hexes = b.degenerate_hexes.size();
    for (std::size_t i = 0; i < b.non_manifold_edges.size() && i < max_listed; ++i)
        t.first_non_manifold_edges.push_back(
            locate(mesh, {b.non_manifold_edges[i].a, b.non_manifold_edges[i].b}, b.non_manifold_edges[i].quads));
    for (std::size_t i = 0; i < b.misoriented_edges.size() && i < max_listed; ++i)
        t.first_misoriented_edges.push_back(locate(mesh, {b.misoriented_edges[i][0], b.misoriented_edges[i][1]}, 2));
    for (std::size_t i = 0; i < b.non_manifold_vertices.size() && i < max_listed; ++i)
        t.first_non_manifold_vertices.push_back(locate(mesh, {b.non_manifold_vertices[i]}, 0));
    for (std::size_t i = 0; i < b.face_defects.size() && i < max_listed; ++i) {
        const auto& c = b.face_defects[i].corners;
        t.first_face_defects.push_back(locate(mesh, {c[0], c[1], c[2], c[3]}, b.face_defects[i].hexes));
    }
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        if (!(scaled_jacobian(mesh, h) > 0)) {
            if (t.inverted_hexes++ < max_listed)
                t.first_inverted_hexes.push_back(
                    locate(mesh, std::vector<int>(mesh.hexes[h].begin(), mesh.hexes[h].end()), 0));
        }
    t.hexes_per_component = hex_component_sizes(mesh.hexes);
    t.hex_components = t.hexes_per_component.size();
    t.boundary_components = polygon_components(b.quads, mesh.points.size());
    return t;
}

std::string HexTopology::summary() const {
    std::ostringstream s;
    s << hexes << " hexes, " << hex_components << " face-connected components; boundary: " << boundary_quads
      << " quads, " << boundary_edges << " edges, " << boundary_vertices << " vertices, " << boundary_components.size()
      << " components, chi";
    for (const auto& c : boundary_components) s << ' ' << c.euler();
    s << "\nnon-manifold edges " << non_manifold_edges << ", misoriented edges " << misoriented_edges
      << ", non-manifold vertices " << non_manifold_vertices << ", face defects " << face_defects
      << ", degenerate hexes " << degenerate_hexes << ", inverted hexes " << inverted_hexes;
    const auto list = [&](const char* what, const std::vector<DefectLocation>& first) {
        for (const auto& d : first) s << "\n  " << what << ": " << d.describe();
    };
    list("non-manifold edge", first_non_manifold_edges);
    list("misoriented edge", first_misoriented_edges);
    list("non-manifold vertex", first_non_manifold_vertices);
    list("face defect", first_face_defects);
    list("inverted hex", first_inverted_hexes);
    return s.str();
}

std::vector<SurfaceComponent> surface_topology(const TriangleSurface& surface) {
    for (std::size_t t = 0; t < surface.triangles.size(); ++t)
        for (int v : surface.triangles[t])
            if (v < 0 || static_cast<std::size_t>(v) >= surface.vertices.size())
                throw std::invalid_argument(surface.source + ": triangle " + std::to_string(t) + ": vertex id " +
                                            std::to_string(v) + " out of range");
    return polygon_components(surface.triangles, surface.vertices.size());
}

TopologyComparison compare_topology(const std::vector<SurfaceComponent>& mesh_boundary,
                                    const std::vector<SurfaceComponent>& surface) {
    TopologyComparison c;
    for (const auto& m : mesh_boundary) c.mesh_euler.push_back(m.euler());
    for (const auto& m : surface) c.surface_euler.push_back(m.euler());
    std::sort(c.mesh_euler.rbegin(), c.mesh_euler.rend());
    std::sort(c.surface_euler.rbegin(), c.surface_euler.rend());
    c.same = c.mesh_euler == c.surface_euler;
    return c;
}

TopologyComparison compare_topology(const HexTopology& mesh, const TriangleSurface& surface) {
    return compare_topology(mesh.boundary_components, surface_topology(surface));
}

std::string TopologyComparison::describe() const {
    const auto set = [](const std::vector<std::int64_t>& v) {
        std::string s = "{";
        for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
        return s + "}";
    };
    return "boundary chi " + set(mesh_euler) + " vs surface chi " + set(surface_euler) +
           (same ? " (same)" : " (differ)");
}

}  // namespace dualhex::geometry
