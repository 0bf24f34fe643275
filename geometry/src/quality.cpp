#include "dualhex/geometry/quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "dualhex/geometry/parallel_each.hpp"

namespace dualhex::geometry {

using Eigen::Vector3d;

double scaled_jacobian(const std::array<Vector3d, 8>& x) {
    double worst = std::numeric_limits<double>::infinity();
    for (int c = 0; c < 8; ++c) {
        const auto& n = kScaledJacobianCorners[c];
        const std::optional<double> term = corner_scaled_jacobian(x[c], x[n[0]], x[n[1]], x[n[2]]);
        if (!term) return 0.0;
        worst = std::min(worst, *term);
    }
    return worst;
}

double scaled_jacobian(const HexMesh& mesh, std::size_t hex) {
    std::array<Vector3d, 8> x;
    for (int n = 0; n < 8; ++n) x[n] = mesh.points[mesh.hexes[hex][n]];
    return scaled_jacobian(x);
}

// Each hex's value written to its own slot: the same for any number of threads.
std::vector<double> scaled_jacobians(const HexMesh& mesh) {
    std::vector<double> out(mesh.hexes.size());
    parallel_each(out.size(), 2048, [&](std::size_t h) { out[h] = scaled_jacobian(mesh, h); });
    return out;
}

QualitySummary summarize(const std::vector<double>& sj) {
    QualitySummary s;
    s.hexes = sj.size();
    if (sj.empty()) return s;
    s.min = *std::min_element(sj.begin(), sj.end());
    double sum = 0;
    std::size_t neg = 0, low = 0;
    for (double v : sj) {
        sum += v;
        neg += v < 0;
        low += v < 0.2;
    }
    const auto n = static_cast<double>(sj.size());
    s.mean = sum / n;
    s.share_negative = static_cast<double>(neg) / n;
    s.share_below_02 = static_cast<double>(low) / n;
    return s;
}

std::vector<std::array<int, 4>> boundary_quads(const HexMesh& mesh) {
    // VTK hex faces, outward (right-hand normal points out of the hex).
    static constexpr int kFace[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                        {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    // Sorted (key, quad) pairs instead of a map: the same quads in the same (key) order.
    struct Use {
        std::array<int, 4> key, quad;
    };
    std::vector<Use> uses;
    uses.reserve(mesh.hexes.size() * 6);
    for (const auto& h : mesh.hexes)
        for (const auto& f : kFace) {
            Use u{{}, {h[f[0]], h[f[1]], h[f[2]], h[f[3]]}};
            u.key = u.quad;
            std::sort(u.key.begin(), u.key.end());
            uses.push_back(u);
        }
    std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) { return a.key < b.key; });
    std::vector<std::array<int, 4>> out;
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i + 1;
        while (j < uses.size() && uses[j].key == uses[i].key) ++j;
        if (j - i == 1) out.push_back(uses[i].quad);
        i = j;
    }
    return out;
}

HausdorffResult boundary_to_surface_distance(const HexMesh& mesh, const AabbTree& tree) {
    const auto quads = boundary_quads(mesh);
    std::vector<char> on_boundary(mesh.points.size(), 0);
    std::vector<Vector3d> samples;
    for (const auto& q : quads) {
        Vector3d centre = Vector3d::Zero();
        for (int v : q) {
            on_boundary[v] = 1;
            centre += mesh.points[v];
        }
        samples.push_back(centre / 4.0);
    }
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        if (on_boundary[v]) samples.push_back(mesh.points[v]);
    HausdorffResult r;
    r.samples = samples.size();
    if (samples.empty()) return r;
    const double diag = tree.bounds().diagonal().norm();
    const std::vector<double> distance = distances(tree, samples);
    double sum = 0;
    for (const double d : distance) {  // in sample order: the same sum for any number of threads
        r.max = std::max(r.max, d);
        sum += d;
    }
    r.max /= diag;
    r.mean = sum / static_cast<double>(samples.size()) / diag;
    return r;
}

}  // namespace dualhex::geometry
