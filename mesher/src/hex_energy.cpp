// The barrier energy and the vertex -> hexes incidence of the optimise stage (hex_energy.hpp).
#include "hex_energy.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace dualhex::mesher::detail {
namespace {

const Eigen::Vector3d& point(const geometry::HexMesh& mesh, int id, int moved, const Eigen::Vector3d& at) {
    return id == moved ? at : mesh.points[static_cast<std::size_t>(id)];
}

// The cofactor matrix of J: d det(J) / dJ.
Eigen::Matrix3d cofactor(const Eigen::Matrix3d& J) {
    Eigen::Matrix3d C;
    C.col(0) = J.col(1).cross(J.col(2));
    C.col(1) = J.col(2).cross(J.col(0));
    C.col(2) = J.col(0).cross(J.col(1));
    return C;
}

// x^(1/3) for the energy's chi^(2/3): libm's cbrt was 15-20 % of a bunny run (perf), this
// is a bit-level first guess (exponent / 3) and three Halley steps (cubic convergence:
// 5 % -> 1e-4 -> 1e-12 -> rounding), pure arithmetic, so the same on every machine.
double cube_root(double x) {
    if (!(x > 1e-300 && x < 1e300)) return std::cbrt(x);  // 0, subnormal, huge, NaN: libm
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    bits = bits / 3 + 0x2a9f7893782da1ceULL;
    double y = 0;
    std::memcpy(&y, &bits, sizeof y);
    for (int i = 0; i < 3; ++i) {
        const double y3 = y * y * y;
        y *= (y3 + 2 * x) / (2 * y3 + x);
    }
    return y;
}

}  // namespace

VertexHexes::VertexHexes(const geometry::HexMesh& mesh) {
    start.assign(mesh.points.size() + 1, 0);
    for (const auto& h : mesh.hexes)
        for (int v : h) ++start[static_cast<std::size_t>(v) + 1];
    for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
    hex.resize(start.back());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t h = 0; h < mesh.hexes.size(); ++h)
        for (int v : mesh.hexes[h]) hex[fill[static_cast<std::size_t>(v)]++] = static_cast<int>(h);
}

BarrierEnergy::BarrierEnergy(const geometry::HexMesh& mesh) {
    scale.reserve(mesh.hexes.size());
    for (const auto& h : mesh.hexes) {
        double sum = 0;
        for (int k = 0; k < 8; ++k)
            for (int n : kCornerNeighbours[static_cast<std::size_t>(k)])
                if (n > k) sum += (mesh.points[static_cast<std::size_t>(h[static_cast<std::size_t>(n)])] -
                                   mesh.points[static_cast<std::size_t>(h[static_cast<std::size_t>(k)])])
                                      .norm();
        scale.push_back(sum > 0 ? 12.0 / sum : 1.0);
    }
}

Eigen::Matrix3d corner_jacobian(const geometry::HexMesh& mesh, std::size_t h, int k, int moved,
                                const Eigen::Vector3d& at) {
    const auto& hex = mesh.hexes[h];
    const auto& nb = kCornerNeighbours[static_cast<std::size_t>(k)];
    const Eigen::Vector3d& o = point(mesh, hex[static_cast<std::size_t>(k)], moved, at);
    Eigen::Matrix3d J;
    for (int i = 0; i < 3; ++i)
        J.col(i) = point(mesh, hex[static_cast<std::size_t>(nb[static_cast<std::size_t>(i)])], moved, at) - o;
    return J;
}

double BarrierEnergy::corner(const Eigen::Matrix3d& J, Eigen::Matrix3d* gradient) const {
    const Eigen::Matrix3d C = cofactor(J);
    const double D = J.col(0).dot(C.col(0));  // det J
    const double root = std::sqrt(eps * eps + D * D);
    const double chi = 0.5 * (D + root), dchi = 0.5 * (1 + D / root);
    const double trace = J.squaredNorm();
    const double c23 = cube_root(chi * chi);
    const double shape = trace / c23, volume = (D * D + 1) / chi;
    if (gradient)
        *gradient = 2.0 / c23 * J +
                    (-2.0 / 3.0 * shape / chi * dchi + lambda * (2 * D / chi - volume / chi * dchi)) * C;
    return shape + lambda * volume;
}

double BarrierEnergy::hex(const geometry::HexMesh& mesh, std::size_t h, int moved, const Eigen::Vector3d& at,
                          Eigen::Vector3d* gradient) const {
    const auto& ids = mesh.hexes[h];
    const double s = scale[h];
    double sum = 0;
    for (int k = 0; k < 8; ++k) {
        const auto& nb = kCornerNeighbours[static_cast<std::size_t>(k)];
        const bool involved = ids[static_cast<std::size_t>(k)] == moved || ids[static_cast<std::size_t>(nb[0])] == moved ||
                              ids[static_cast<std::size_t>(nb[1])] == moved || ids[static_cast<std::size_t>(nb[2])] == moved;
        if (moved >= 0 && !involved) continue;  // constant in `at`: left out of the local energy
        Eigen::Matrix3d G;
        sum += corner(s * corner_jacobian(mesh, h, k, moved, at), gradient ? &G : nullptr);
        if (!gradient) continue;
        // J = s [p_a - p_k, p_b - p_k, p_c - p_k]: d/dp_a = s G.col(0), ..., d/dp_k = -s (sum of columns).
        for (int i = 0; i < 3; ++i)
            if (ids[static_cast<std::size_t>(nb[static_cast<std::size_t>(i)])] == moved) *gradient += s * G.col(i);
        if (ids[static_cast<std::size_t>(k)] == moved) *gradient -= s * G.rowwise().sum();
    }
    return sum;
}

double BarrierEnergy::hex_newton(const geometry::HexMesh& mesh, std::size_t h, int moved, const Eigen::Vector3d& at,
                                 Eigen::Vector3d& gradient, Eigen::Matrix3d& hessian) const {
    const auto& ids = mesh.hexes[h];
    const double s = scale[h];
    double sum = 0;
    for (int k = 0; k < 8; ++k) {
        // w: how the moved point enters J's columns (J = J0 + s (at - at0) w^T).
        const auto& nb = kCornerNeighbours[static_cast<std::size_t>(k)];
        Eigen::Vector3d w = Eigen::Vector3d::Zero();
        if (ids[static_cast<std::size_t>(k)] == moved) w.setConstant(-1);
        for (int i = 0; i < 3; ++i)
            if (ids[static_cast<std::size_t>(nb[static_cast<std::size_t>(i)])] == moved) w[i] = 1;
        if (w.isZero()) continue;
        const Eigen::Matrix3d J = s * corner_jacobian(mesh, h, k, moved, at);
        const Eigen::Matrix3d C = cofactor(J);
        const double D = J.col(0).dot(C.col(0));
        const double r = std::sqrt(eps * eps + D * D);
        const double chi = 0.5 * (D + r), d1 = chi / r, d2 = 0.5 * eps * eps / (r * r * r);  // chi, chi', chi''
        const double T = J.squaredNorm();
        const double c23 = cube_root(chi * chi), phi = 1 / c23;  // chi^(2/3), chi^(-2/3)
        const double phi1 = -2.0 / 3.0 * phi / chi * d1;
        const double phi2 = 10.0 / 9.0 * phi / (chi * chi) * d1 * d1 - 2.0 / 3.0 * phi / chi * d2;
        const double q = D * D + 1;
        const double psi = q / chi, psi1 = 2 * D / chi - q * d1 / (chi * chi);
        const double psi2 = 2 / chi - 4 * D * d1 / (chi * chi) - q * d2 / (chi * chi) + 2 * q * d1 * d1 / (chi * chi * chi);
        const Eigen::Vector3d a = s * (C * w);        // d D / d at (constant along at)
        const Eigen::Vector3d b = 2 * s * (J * w);    // d T / d at
        sum += T / c23 + lambda * psi;  // as corner() computes it, to the last bit
        gradient += phi * b + (T * phi1 + lambda * psi1) * a;
        hessian += (2 * s * s * w.squaredNorm() * phi) * Eigen::Matrix3d::Identity() + phi1 * (b * a.transpose() + a * b.transpose()) +
                   (T * phi2 + lambda * psi2) * (a * a.transpose());
    }
    return sum;
}

double BarrierEnergy::min_det(const geometry::HexMesh& mesh, std::size_t h) const {
    double m = INFINITY;
    for (int k = 0; k < 8; ++k) m = std::min(m, (scale[h] * corner_jacobian(mesh, h, k, -1, Eigen::Vector3d::Zero())).determinant());
    return m;
}

}  // namespace dualhex::mesher::detail
