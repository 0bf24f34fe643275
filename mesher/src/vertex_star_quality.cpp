// VertexStarQuality (optimise_detail.hpp): the quality phase's trial positions of one vertex
// re-evaluate only the corner terms that read it. Each visit tries up to 31 positions (the
// numerical gradient and three line searches), and local_quality's full scaled Jacobians were
// the largest single cost of a bunny run (perf, 2026-12-03).
#include <limits>

#include "dualhex/geometry/quality.hpp"
#include "optimise_detail.hpp"

namespace dualhex::mesher::detail {
namespace {

// The term of corner k of `hex`, with point v at x.
std::optional<double> corner_term(const geometry::HexMesh& mesh, const std::array<int, 8>& hex, int k, std::size_t v,
                                  const Eigen::Vector3d& x) {
    const auto at = [&](int corner) -> const Eigen::Vector3d& {
        const auto id = static_cast<std::size_t>(hex[static_cast<std::size_t>(corner)]);
        return id == v ? x : mesh.points[id];
    };
    const auto& n = geometry::kScaledJacobianCorners[k];
    return geometry::corner_scaled_jacobian(at(k), at(n[0]), at(n[1]), at(n[2]));
}

}  // namespace

VertexStarQuality::VertexStarQuality(const OptimiseContext& c, std::size_t v) : c_(c), v_(v) {
    hexes_.reserve(c.incidence.count(v));
    for (std::size_t i = c.incidence.start[v]; i < c.incidence.start[v + 1]; ++i) {
        HexTerms t;
        t.hex = static_cast<std::size_t>(c.incidence.hex[i]);
        const auto& hex = c.mesh.hexes[t.hex];
        const auto reads = [&](int corner) { return static_cast<std::size_t>(hex[static_cast<std::size_t>(corner)]) == v; };
        for (int k = 0; k < 8; ++k) {
            const auto& n = geometry::kScaledJacobianCorners[k];
            if (reads(k) || reads(n[0]) || reads(n[1]) || reads(n[2])) t.reads_v |= static_cast<std::uint8_t>(1U << k);
            else t.term[static_cast<std::size_t>(k)] = corner_term(c.mesh, hex, k, v, c.mesh.points[v]);
        }
        hexes_.push_back(t);
    }
}

LocalQuality VertexStarQuality::at(const Eigen::Vector3d& x) const {
    LocalQuality q;
    for (const HexTerms& t : hexes_) {
        const auto& hex = c_.mesh.hexes[t.hex];
        double s = std::numeric_limits<double>::infinity();
        for (int k = 0; k < 8; ++k) {
            const std::optional<double> term =
                (t.reads_v >> k) & 1U ? corner_term(c_.mesh, hex, k, v_, x) : t.term[static_cast<std::size_t>(k)];
            if (!term) {  // a zero-length edge: the hex's value is 0 (geometry::scaled_jacobian)
                s = 0.0;
                break;
            }
            s = std::min(s, *term);
        }
        count_hex(q, s, c_.bad_below);
    }
    return q;
}

}  // namespace dualhex::mesher::detail
