// manifold_repair_bench: repair_manifold_selection (manifold_repair.hpp) on real surfaces,
// without the mesher: the complex is a uniform N^3 lattice of hexes over the surface's
// bounding box (enlarged 5% per side), a cell is selected iff its centre is inside
// (is_inside), its score is the signed distance of its centre (+ inside). Thin parts of
// the shared models give the same edge/vertex contacts the octree dual shows. Prints, per
// surface: the selection's defects before and after, the changes, the rounds, the
// boundary chi against the surface's, and the repair's time. Not part of the test suite.
//
//   manifold_repair_bench [N] SURFACE...      (default N = 48)
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "dualhex/geometry/aabb_tree.hpp"
#include "dualhex/geometry/hex_topology.hpp"
#include "dualhex/geometry/inside.hpp"
#include "dualhex/geometry/manifold_repair.hpp"
#include "dualhex/geometry/surface.hpp"

using namespace dualhex::geometry;

namespace {

struct Lattice {
    std::vector<std::array<int, 8>> cells;
    std::vector<Eigen::Vector3d> points;
};

Lattice lattice_over(const Eigen::AlignedBox3d& box, int n) {
    const Eigen::Vector3d lo = box.min() - 0.05 * box.sizes(), size = 1.1 * box.sizes();
    Lattice l;
    auto id = [&](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i)
                l.points.push_back(lo + size.cwiseProduct(Eigen::Vector3d(i, j, k)) / static_cast<double>(n));
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                l.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                                   id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
    return l;
}

HexMesh selected_hexes(const Lattice& l, const std::vector<char>& selected) {
    HexMesh m;
    m.points = l.points;  // unused points do not change the boundary topology
    for (std::size_t c = 0; c < l.cells.size(); ++c)
        if (selected[c]) m.hexes.push_back(l.cells[c]);
    return m;
}

std::string chi_text(const std::vector<SurfaceComponent>& cs) {
    std::int64_t chi = 0;
    for (const auto& c : cs) chi += c.euler();
    return std::to_string(chi) + "(" + std::to_string(cs.size()) + ")";
}

void run(const std::string& path, int n) {
    const AabbTree tree(read_surface(path));
    const Lattice l = lattice_over(tree.bounds(), n);
    std::vector<char> selected(l.cells.size());
    std::vector<double> score(l.cells.size());
    for (std::size_t c = 0; c < l.cells.size(); ++c) {
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int v : l.cells[c]) centre += l.points[static_cast<std::size_t>(v)];
        centre /= 8.0;
        selected[c] = is_inside(tree, centre);
        score[c] = (selected[c] ? 1.0 : -1.0) * std::sqrt(tree.squared_distance(centre));
    }
    const HexTopology before = check_hex_topology(selected_hexes(l, selected), 0);
    const auto t0 = std::chrono::steady_clock::now();
    const ManifoldRepairResult r = repair_manifold_selection(l.cells, l.points.size(), selected, score);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const HexTopology after = check_hex_topology(selected_hexes(l, r.selected), 0);
    std::size_t added = 0;
    for (const auto& c : r.changes) added += c.selected;
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("%-20s %7zu %5zu %5zu %4zu | %5zu %5zu %4d | %5zu %5zu %4zu | %8s %8s %8s | %7.0f\n", name.c_str(),
                before.hexes, before.non_manifold_edges, before.non_manifold_vertices, before.hex_components, added,
                r.changes.size() - added, r.rounds, after.non_manifold_edges, after.non_manifold_vertices,
                after.hex_components, chi_text(before.boundary_components).c_str(),
                chi_text(after.boundary_components).c_str(), chi_text(surface_topology(tree.surface())).c_str(), ms);
}

}  // namespace

int main(int argc, char** argv) {
    int first = 1, n = 48;
    if (argc > 1 && std::isdigit(static_cast<unsigned char>(argv[1][0]))) {
        n = std::stoi(argv[1]);
        first = 2;
    }
    std::printf("lattice %d^3; before: selected hexes, non-manifold edges / vertices, face components | changes: added, "
                "removed, rounds | after: nmE nmV comp | boundary chi(components) before, after, surface | repair ms\n",
                n);
    for (int a = first; a < argc; ++a) try {
            run(argv[a], n);
        } catch (const std::exception& e) {
            std::printf("%s: error: %s\n", argv[a], e.what());
        }
}
