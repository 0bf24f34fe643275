// The surface-to-hex-mesh pipeline (mesh_pipeline.hpp).
#include "dualhex/geometry/mesh_pipeline.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "dualhex/checkers/install.hpp"
#include "dualhex/checkers/library.hpp"
#include "dualhex/geometry/inside.hpp"
#include "dualhex/grid/refinement.hpp"
#include "dualhex/schemes/signature_rule.hpp"
#include "dualhex/schemes/weak_rule.hpp"
#include "dualhex/topology/clipped_dual.hpp"
#include "dualhex/topology/incidence.hpp"

namespace dualhex::geometry {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// The 12 edges of a hex in VTK_HEXAHEDRON order.
constexpr std::array<std::array<int, 2>, 12> kHexEdges{{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}}};

std::uint64_t edge_key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

std::vector<char> boundary_vertex_flags(const HexMesh& mesh, const std::vector<std::array<int, 4>>& quads) {
    std::vector<char> on(mesh.points.size(), 0);
    for (const auto& q : quads)
        for (int v : q) on[static_cast<std::size_t>(v)] = 1;
    return on;
}

std::size_t count_inverted_in(const std::vector<double>& sj) {
    return static_cast<std::size_t>(std::count_if(sj.begin(), sj.end(), [](double s) { return !(s > 0); }));
}

}  // namespace

std::size_t count_inverted(const HexMesh& mesh) { return count_inverted_in(scaled_jacobians(mesh)); }

std::map<int, std::size_t> interior_singular_edge_valences(const HexMesh& mesh) {
    std::unordered_map<std::uint64_t, int> hexes_at;
    hexes_at.reserve(mesh.hexes.size() * 4);
    for (const auto& h : mesh.hexes)
        for (const auto& e : kHexEdges) ++hexes_at[edge_key(h[e[0]], h[e[1]])];
    std::unordered_map<std::uint64_t, char> boundary;
    for (const auto& q : boundary_quads(mesh))
        for (int i = 0; i < 4; ++i) boundary[edge_key(q[i], q[(i + 1) % 4])] = 1;
    std::map<int, std::size_t> out;
    for (const auto& [key, n] : hexes_at)
        if (n != 4 && !boundary.contains(key)) ++out[n];
    return out;
}

TriangleSurface default_shape() {
    constexpr int nu = 48, nv = 24;
    constexpr double R = 1.0, r = 0.4;
    TriangleSurface s;
    s.source = "<default torus>";
    for (int i = 0; i < nu; ++i) {
        const double u = 2 * std::numbers::pi * i / nu;
        for (int j = 0; j < nv; ++j) {
            const double v = 2 * std::numbers::pi * j / nv;
            s.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
                                    r * std::sin(v));
        }
    }
    auto id = [&](int i, int j) { return ((i + nu) % nu) * nv + (j + nv) % nv; };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            s.triangles.push_back({a, b, c});
            s.triangles.push_back({a, c, d});
        }
    // clean_surface checks closedness and flips the orientation outward if needed.
    return clean_surface(std::move(s));
}

MeshPipelineResult mesh_surface(const AabbTree& tree, const MeshPipelineOptions& options) {
    if (options.max_depth < 1 || options.max_depth > 12)
        throw std::invalid_argument("max depth must be in [1, 12], got " + std::to_string(options.max_depth));
    if (options.smooth_iterations < 0) throw std::invalid_argument("smoothing iterations must be >= 0");
    auto stage = [&](const char* name) {
        if (options.progress) options.progress(name);
    };
    MeshPipelineResult result;

    // 1. octree, 2. pairing + balancing
    stage("octree");
    auto t0 = Clock::now();
    SurfaceOctreeOptions octree_options;
    octree_options.max_depth = options.max_depth;
    SurfaceOctree octree = surface_octree(tree, octree_options);
    result.ms.octree = ms_since(t0);
    result.root = octree.root;

    stage("balance");
    t0 = Clock::now();
    const LeafGrid balanced = balance(octree.grid, options.balance);
    result.ms.balance = ms_since(t0);

    stage("pair");
    t0 = Clock::now();
    const LeafGrid grid = pair(balanced, options.balance);
    result.ms.pair = ms_since(t0);
    result.ms.balance_pair = result.ms.balance + result.ms.pair;
    result.leaves = grid.size();

    // 3. install + verify
    stage("install");
    t0 = Clock::now();
    const auto library = load_default_element_library();
    const InstallOptions install_options{.outside_root = OutsideRoot::Coarse, .balance = options.balance};
    const InstallResult installed = options.balance == Balance::Strong
                                        ? install(grid, StrongRule(), *library, install_options)
                                        : install(grid, WeakRule(), *library, install_options);
    result.ms.install = ms_since(t0);
    result.cells = installed.complex.n_cells();

    stage("verify");
    t0 = Clock::now();
    const InstallVerification verification = verify_installation(installed);
    result.ms.verify = ms_since(t0);
    if (!verification.ok()) throw std::runtime_error("installation does not verify: " + verification.summary());

    // 4. clipped dual
    stage("dual");
    t0 = Clock::now();
    const std::int64_t extent = installed.unit << installed.max_level;
    const ClippedDual dual = [&] {
        const Incidence incidence(installed.complex);
        return clipped_dual(installed.complex, incidence, {0, 0, 0}, {extent, extent, extent});
    }();
    result.ms.dual = ms_since(t0);
    if (!dual.all_cubes())
        throw std::runtime_error("clipped dual: " + std::to_string(dual.errors.size()) +
                                 " vertices without a cube, e.g. " + dual.errors.front().message);
    result.dual_hexes = dual.hexes.size();
    result.dual_edge_valences = clipped_dual_edge_valences(dual);

    // 5. embed + extract the hexes whose centroid is inside
    stage("extract");
    t0 = Clock::now();
    const double ext = static_cast<double>(extent);
    std::vector<Eigen::Vector3d> all_points;
    all_points.reserve(dual.points.size());
    for (const RationalPoint& p : dual.points)
        all_points.push_back(octree.root.origin +
                             octree.root.size * Eigen::Vector3d(p.coordinate(0, ext), p.coordinate(1, ext),
                                                                p.coordinate(2, ext)));
    std::vector<int> new_id(all_points.size(), -1);
    HexMesh& mesh = result.mesh;
    for (const auto& h : dual.hexes) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (std::uint32_t v : h) c += all_points[v];
        c /= 8.0;
        if (!is_inside(tree, c)) continue;
        std::array<int, 8> q{};
        for (std::size_t i = 0; i < 8; ++i) {
            int& id = new_id[h[i]];
            if (id < 0) {
                id = static_cast<int>(mesh.points.size());
                mesh.points.push_back(all_points[h[i]]);
            }
            q[i] = id;
        }
        mesh.hexes.push_back(q);
    }
    result.ms.extract = ms_since(t0);
    if (mesh.hexes.empty()) throw std::runtime_error("no hex centroid inside the surface (max depth too small?)");

    // 6. project the boundary vertices
    stage("project");
    t0 = Clock::now();
    const auto quads = boundary_quads(mesh);
    const std::vector<char> on_boundary = boundary_vertex_flags(mesh, quads);
    const std::vector<Eigen::Vector3d> unprojected = mesh.points;  // the embedded dual positions
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (on_boundary[v]) {
            mesh.points[v] = tree.closest_point(mesh.points[v]).point;
            ++result.boundary_vertices;
        }
    std::vector<double> sj = scaled_jacobians(mesh);
    std::size_t inverted = count_inverted_in(sj);
    result.inverted_after_projection = inverted;
    result.ms.project = ms_since(t0);

    // 7. Laplacian smoothing of the interior vertices
    stage("smooth");
    t0 = Clock::now();
    if (options.smooth_iterations > 0) {
        // vertex adjacency (hex edges), CSR
        std::vector<std::uint64_t> edges;
        edges.reserve(mesh.hexes.size() * 12);
        for (const auto& h : mesh.hexes)
            for (const auto& e : kHexEdges) edges.push_back(edge_key(h[e[0]], h[e[1]]));
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        std::vector<std::size_t> start(mesh.points.size() + 1, 0);
        for (auto k : edges) {
            ++start[(k >> 32) + 1];
            ++start[(k & 0xffffffffu) + 1];
        }
        for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
        std::vector<int> adj(start.back());
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        for (auto k : edges) {
            const auto a = static_cast<std::size_t>(k >> 32), b = static_cast<std::size_t>(k & 0xffffffffu);
            adj[fill[a]++] = static_cast<int>(b);
            adj[fill[b]++] = static_cast<int>(a);
        }
        std::vector<Eigen::Vector3d> next;
        for (int it = 0; it < options.smooth_iterations; ++it) {
            next = mesh.points;
            for (std::size_t v = 0; v < mesh.points.size(); ++v) {
                if (on_boundary[v] || start[v] == start[v + 1]) continue;
                Eigen::Vector3d m = Eigen::Vector3d::Zero();
                for (std::size_t i = start[v]; i < start[v + 1]; ++i) m += mesh.points[static_cast<std::size_t>(adj[i])];
                next[v] = m / static_cast<double>(start[v + 1] - start[v]);
            }
            std::swap(next, mesh.points);
            std::vector<double> sj_next = scaled_jacobians(mesh);
            const std::size_t inverted_next = count_inverted_in(sj_next);
            if (inverted_next > inverted) {  // rejected: restore and stop
                std::swap(next, mesh.points);
                break;
            }
            sj = std::move(sj_next);
            inverted = inverted_next;
            ++result.smooth_iterations_done;
        }
    }
    result.ms.smooth = ms_since(t0);

    // 8. untangle: pull the boundary vertices of inverted hexes back towards their
    // unprojected positions
    stage("untangle");
    t0 = Clock::now();
    auto count_bad = [&](const std::vector<double>& values) {
        return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [&](double q) {
            return !(q > 0) || q < options.untangle_below;
        }));
    };
    std::size_t bad = count_bad(sj);
    for (int round = 0; round < options.untangle_rounds && bad > 0; ++round) {
        std::vector<char> move(mesh.points.size(), 0);
        for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
            if (!(sj[h] > 0) || sj[h] < options.untangle_below)
                for (int v : mesh.hexes[h]) move[static_cast<std::size_t>(v)] = 1;
        const std::vector<Eigen::Vector3d> before = mesh.points;
        std::size_t moved = 0;
        for (std::size_t v = 0; v < mesh.points.size(); ++v)
            if (move[v]) {
                mesh.points[v] = unprojected[v] + 0.5 * (mesh.points[v] - unprojected[v]);
                ++moved;
            }
        std::vector<double> sj_next = scaled_jacobians(mesh);
        const std::size_t inverted_next = count_inverted_in(sj_next), bad_next = count_bad(sj_next);
        if (inverted_next > inverted || (inverted_next == inverted && bad_next > bad)) {
            mesh.points = before;
            break;
        }
        result.untangled_vertices += moved;
        sj = std::move(sj_next);
        inverted = inverted_next;
        bad = bad_next;
    }
    result.ms.untangle = ms_since(t0);

    // 9. report
    stage("report");
    t0 = Clock::now();
    result.quality = summarize(sj);
    result.singular_edge_valences = interior_singular_edge_valences(mesh);
    result.hausdorff = boundary_to_surface_distance(mesh, tree);
    result.ms.report = ms_since(t0);
    return result;
}

}  // namespace dualhex::geometry
