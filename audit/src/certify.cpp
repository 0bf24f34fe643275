#include "dualhex/audit/certify.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "audit_modes.hpp"

namespace dualhex::audit {
namespace {

// The smallest K in [0, 64] with x * 2^K an integer, or -1. Scaling by 2^K is exact.
int dyadic_exponent(double x) {
    for (int k = 0; k <= 64; ++k) {
        const double s = std::ldexp(x, k);
        if (std::floor(s) == s) return k;
    }
    return -1;
}

std::string point_text(const MeshFile& mesh, std::size_t p) {
    std::ostringstream os;
    os.precision(17);
    const auto& c = mesh.points[p];
    os << "point " << p << " (" << c[0] << ' ' << c[1] << ' ' << c[2] << ')';
    return os.str();
}

}  // namespace

std::optional<CertificateComplex> certificate_complex(const MeshFile& mesh, std::string& refusal) {
    std::vector<char> used(mesh.points.size(), 0);
    for (const MeshCell& c : mesh.cells)
        for (const auto& f : detail::cell_faces(c))
            for (std::int64_t p : f) used[static_cast<std::size_t>(p)] = 1;
    int k_max = 0;
    std::size_t k_point = 0;  // a point needing 2^k_max
    for (std::size_t p = 0; p < mesh.points.size(); ++p)
        for (double x : mesh.points[p])
            if (used[p]) {
                const int k = dyadic_exponent(x);
                if (k < 0) {
                    refusal = point_text(mesh, p) + " has a coordinate x with no x * 2^K integral for K <= 64";
                    return std::nullopt;
                }
                if (k > k_max) k_max = k, k_point = p;
            }
    std::vector<LatticePoint> positions(mesh.points.size());
    std::map<LatticePoint, std::size_t> first_at;
    for (std::size_t p = 0; p < mesh.points.size(); ++p) {
        if (!used[p]) continue;
        for (int a = 0; a < 3; ++a) {
            const double s = std::ldexp(mesh.points[p][static_cast<std::size_t>(a)], k_max);
            if (std::fabs(s) > static_cast<double>(kCertificateCoordinateBound)) {
                refusal = "coordinates are integral only once scaled by 2^" + std::to_string(k_max) + " (" +
                          point_text(mesh, k_point) + "), and then " + point_text(mesh, p) +
                          " exceeds the checker's bound |x| <= 2^19";
                return std::nullopt;
            }
            positions[p][a] = static_cast<std::int64_t>(s);
        }
        const auto [it, fresh] = first_at.emplace(positions[p], p);
        if (!fresh) {
            refusal = point_text(mesh, p) + " and " + point_text(mesh, it->second) +
                      " are at the same position (the checker requires distinct positions)";
            return std::nullopt;
        }
    }
    CertificateComplex out;
    out.scale_exponent = k_max;
    out.complex = detail::build_complex(mesh, positions).complex;
    const auto& pos = out.complex.positions();
    if (!pos.empty()) out.lo = out.hi = pos.front();
    for (const LatticePoint& q : pos)
        for (int a = 0; a < 3; ++a) {
            out.lo[a] = std::min(out.lo[a], q[a]);
            out.hi[a] = std::max(out.hi[a], q[a]);
        }
    for (int a = 0; a < 3; ++a)
        if (out.hi[a] - out.lo[a] > kCertificateCoordinateBound) {
            refusal = "the scaled points span " + std::to_string(out.hi[a] - out.lo[a]) + " along axis " +
                      std::to_string(a) + ", more than the checker's box extent 2^19";
            return std::nullopt;
        }
    return out;
}

}  // namespace dualhex::audit
