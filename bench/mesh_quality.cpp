// mesh_quality: an independent measurement of a hex mesh against the surface it should
// match (issue 12). Reads a legacy ASCII VTK hex grid with its own reader and measures it
// with its own code (mesh_quality_*.hpp); only the surface is read with the geometry
// layer's read_surface (input, not measurement). Prints one table row:
//
//   mesh_quality [--header] [--fit] MESH.vtk SURFACE [NAME]
//
// --fit: the mesh is in another frame than the surface (the HybridOctree reference
// meshes are scaled by about 100): it is first mapped by the similarity (uniform scale +
// translation) that takes its boundary's bounding box centre and diagonal to the
// surface's. An approximation (bounding boxes of a mesh and its surface differ a little),
// marked by a '*' after the name.
//
// Columns: hexes; min scaled Jacobian; share of hexes with SJ < 0.3 and < 0.5 (%);
// inverted (SJ <= 0); two-sided distance mean and max (% of the surface's bbox
// diagonal; samples spaced diagonal / 500 on both sides, mean = average of the two
// directions' sample means); on = share of boundary vertices within 1e-6 diagonal of the
// surface (%); nmE / nmV = non-manifold boundary edges / vertices; comp = face-connected
// hex components; bcomp = boundary components / the surface's; chi = boundary Euler
// characteristic / the surface's; maxV = largest interior edge valence; sing = share of
// interior edges with valence != 4 (%).
// Exit: 0, 2 usage, 3 unreadable input (the message names file and line).
#include <cstdio>
#include <iostream>
#include <set>
#include <string>

#include "dualhex/geometry/surface.hpp"
#include "mesh_quality_distance.hpp"
#include "mesh_quality_measures.hpp"

namespace {

using namespace mesh_quality;

struct SurfaceFacts {
    std::vector<Triangle> triangles;
    double diagonal = 0;
    std::size_t components = 0;
    std::int64_t euler = 0;
};

SurfaceFacts surface_facts(const dualhex::geometry::TriangleSurface& s) {
    SurfaceFacts f;
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    std::set<Edge> edges;
    std::set<int> used;
    Dsu pieces(s.vertices.size());
    for (const auto& t : s.triangles) {
        Triangle tri;
        for (int i = 0; i < 3; ++i) {
            const auto& p = s.vertices[static_cast<std::size_t>(t[static_cast<std::size_t>(i)])];
            tri[static_cast<std::size_t>(i)] = {p.x(), p.y(), p.z()};
            lo = {std::min(lo.x, p.x()), std::min(lo.y, p.y()), std::min(lo.z, p.z())};
            hi = {std::max(hi.x, p.x()), std::max(hi.y, p.y()), std::max(hi.z, p.z())};
            edges.insert(edge_of(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]));
            used.insert(t[static_cast<std::size_t>(i)]);
            pieces.join(static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[static_cast<std::size_t>(i)]));
        }
        f.triangles.push_back(tri);
    }
    for (int v : used) f.components += pieces.root(static_cast<std::size_t>(v)) == static_cast<std::size_t>(v);
    f.euler = static_cast<std::int64_t>(used.size()) - static_cast<std::int64_t>(edges.size()) +
              static_cast<std::int64_t>(s.triangles.size());
    const Vec3 d = hi - lo;
    f.diagonal = std::sqrt(dot(d, d));
    return f;
}

void print_header() {
    std::printf("%-20s %7s %7s %6s %6s %5s %7s %7s %6s %5s %5s %4s %7s %7s %4s %6s\n", "mesh", "hexes", "minSJ",
                "<0.3%", "<0.5%", "inv", "mean%", "max%", "on%", "nmE", "nmV", "comp", "bcomp", "chi", "maxV", "sing%");
}

struct Box {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    void add(const Vec3& p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    [[nodiscard]] Vec3 centre() const { return 0.5 * (lo + hi); }
    [[nodiscard]] double diagonal() const { return std::sqrt(dot(hi - lo, hi - lo)); }
};

// Maps g by the similarity taking its boundary's bbox to the surface triangles' bbox.
void fit_to(HexGrid& g, const Topology& t, const std::vector<Triangle>& surface) {
    Box mesh, target;
    for (const auto& q : t.boundary)
        for (auto v : q) mesh.add(g.points[static_cast<std::size_t>(v)]);
    for (const auto& tri : surface)
        for (const auto& p : tri) target.add(p);
    const double scale = target.diagonal() / mesh.diagonal();
    for (auto& p : g.points) p = target.centre() + scale * (p - mesh.centre());
}

int measure(const std::string& mesh_path, const std::string& surface_path, std::string name, bool fit) {
    HexGrid g = read_vtk_hexes(mesh_path);
    if (g.hexes.empty()) throw std::runtime_error(mesh_path + ": no hexahedra");
    const SurfaceFacts s = surface_facts(dualhex::geometry::read_surface(surface_path));
    const Topology t = measure_topology(g);
    if (fit) {
        fit_to(g, t, s.triangles);
        name += '*';
    }
    double min_sj = 1e300;
    std::size_t below03 = 0, below05 = 0, inverted = 0;
    for (const auto& h : g.hexes) {
        const double q = scaled_jacobian(g, h);
        min_sj = std::min(min_sj, q);
        below03 += q < 0.3;
        below05 += q < 0.5;
        inverted += !(q > 0);
    }
    std::vector<Triangle> boundary;
    std::set<std::int64_t> boundary_vertices;
    for (const auto& q : t.boundary) {
        auto p = [&](int i) { return g.points[static_cast<std::size_t>(q[static_cast<std::size_t>(i)])]; };
        boundary.push_back({p(0), p(1), p(2)});
        boundary.push_back({p(0), p(2), p(3)});
        boundary_vertices.insert(q.begin(), q.end());
    }
    const double spacing = s.diagonal / 500;
    const TriangleGrid to_surface(s.triangles), to_mesh(boundary);
    const OneWay out = one_way(boundary, to_surface, spacing), back = one_way(s.triangles, to_mesh, spacing);
    std::size_t on = 0;
    for (auto v : boundary_vertices)
        on += to_surface.distance(g.points[static_cast<std::size_t>(v)]) <= 1e-6 * s.diagonal;
    std::size_t interior = 0, singular = 0;
    int max_valence = 0;
    for (const auto& [valence, n] : t.interior_valences) {
        interior += n;
        singular += valence != 4 ? n : 0;
        max_valence = std::max(max_valence, valence);
    }
    const auto pct = [](double part, double whole) { return whole > 0 ? 100.0 * part / whole : 0.0; };
    const double nh = static_cast<double>(g.hexes.size());
    std::printf(
        "%-20s %7zu %7.3f %6.2f %6.2f %5zu %7.3f %7.3f %6.1f %5zu %5zu %4zu %3zu/%-3zu %3lld/%-3lld %4d %6.2f\n",
        name.c_str(), g.hexes.size(), min_sj, pct(static_cast<double>(below03), nh),
        pct(static_cast<double>(below05), nh), inverted, pct(0.5 * (out.mean + back.mean), s.diagonal),
        pct(std::max(out.max, back.max), s.diagonal),
        pct(static_cast<double>(on), static_cast<double>(boundary_vertices.size())), t.non_manifold_edges,
        t.non_manifold_vertices, t.components, t.boundary_components, s.components,
        static_cast<long long>(t.boundary_euler), static_cast<long long>(s.euler), max_valence,
        pct(static_cast<double>(singular), static_cast<double>(interior)));
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (!args.empty() && args[0] == "--header") {
        print_header();
        args.erase(args.begin());
        if (args.empty()) return 0;
    }
    const bool fit = !args.empty() && args[0] == "--fit";
    if (fit) args.erase(args.begin());
    if (args.size() < 2 || args.size() > 3) {
        std::cerr << "usage: mesh_quality [--header] [--fit] MESH.vtk SURFACE [NAME]\n";
        return 2;
    }
    try {
        return measure(args[0], args[1], args.size() == 3 ? args[2] : args[0], fit);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << '\n';
        return 3;
    }
}
