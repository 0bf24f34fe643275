#include "exact_predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <gmpxx.h>

namespace dualhex::geometry::exact {

namespace {

// Half an ulp of 1: the relative rounding error of one double operation.
constexpr double kEps = 1.0 / 9007199254740992.0;  // 2^-53
// Below this permanent, products may have lost bits to underflow and the relative error
// bounds no longer hold: decide exactly.
constexpr double kTinyPermanent = 1e-250;

// Every finite double is an integer times 2^e (e >= -1074). Scaled by 2^-emin, the
// smallest such exponent among `n` values, all become integers, exactly: integer
// arithmetic (mpz) is much faster than rationals (mpq, which reduce by gcd). Returns
// false if the exponents span so far that the scaling would overflow a double.
template <int N>
bool to_integers(const std::array<double, N>& x, std::array<mpz_class, N>& out) {
    int emin = 1 << 20, emax = -(1 << 20);
    for (double v : x) {
        if (v == 0) continue;
        int e = 0;
        (void)std::frexp(v, &e);  // v = f 2^e, f in [0.5, 1): an integer times 2^(e - 53)
        emin = std::min(emin, e - 53);
        emax = std::max(emax, e);
    }
    if (emax - emin > 1000) return false;
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = x[i] == 0 ? 0.0 : std::ldexp(x[i], -emin);
    return true;
}

template <class Num>
int det3_sign(const Num (&m)[3][3]) {
    const Num det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sgn(det);
}

int orient3d_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d) {
    const std::array<double, 12> x{a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), d.x(), d.y(), d.z()};
    std::array<mpz_class, 12> z;
    if (to_integers<12>(x, z)) {
        mpz_class m[3][3];
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) m[r][k] = z[static_cast<std::size_t>(3 * r + k)] - z[static_cast<std::size_t>(9 + k)];
        return det3_sign(m);
    }
    mpq_class m[3][3];
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[r][k] = mpq_class(x[static_cast<std::size_t>(3 * r + k)]) - mpq_class(x[static_cast<std::size_t>(9 + k)]);
    return det3_sign(m);
}

int orient2d_exact(double ax, double ay, double bx, double by, double cx, double cy) {
    const std::array<double, 6> x{ax, ay, bx, by, cx, cy};
    std::array<mpz_class, 6> z;
    if (to_integers<6>(x, z)) return sgn(mpz_class((z[0] - z[4]) * (z[3] - z[5]) - (z[1] - z[5]) * (z[2] - z[4])));
    const mpq_class det = (mpq_class(ax) - mpq_class(cx)) * (mpq_class(by) - mpq_class(cy)) -
                          (mpq_class(ay) - mpq_class(cy)) * (mpq_class(bx) - mpq_class(cx));
    return sgn(det);
}

}  // namespace

int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
             const Eigen::Vector3d& d) {
    const double adx = a.x() - d.x(), ady = a.y() - d.y(), adz = a.z() - d.z();
    const double bdx = b.x() - d.x(), bdy = b.y() - d.y(), bdz = b.z() - d.z();
    const double cdx = c.x() - d.x(), cdy = c.y() - d.y(), cdz = c.z() - d.z();
    // Four points in one axis-aligned plane (exact: x - y == 0 iff x == y): common in CAD models.
    if ((adx == 0 && bdx == 0 && cdx == 0) || (ady == 0 && bdy == 0 && cdy == 0) || (adz == 0 && bdz == 0 && cdz == 0))
        return 0;
    const double bc = bdx * cdy - cdx * bdy, ca = cdx * ady - adx * cdy, ab = adx * bdy - bdx * ady;
    const double det = adz * bc + bdz * ca + cdz * ab;
    const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * std::fabs(adz) +
                             (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * std::fabs(bdz) +
                             (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * std::fabs(cdz);
    const double bound = (7.0 + 56.0 * kEps) * kEps * permanent;
    if (permanent > kTinyPermanent && std::isfinite(permanent) && std::fabs(det) > bound) return det > 0 ? 1 : -1;
    return orient3d_exact(a, b, c, d);
}

int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    const double l = (ax - cx) * (by - cy), r = (ay - cy) * (bx - cx);
    const double det = l - r, permanent = std::fabs(l) + std::fabs(r);
    const double bound = (3.0 + 16.0 * kEps) * kEps * permanent;
    if (permanent > kTinyPermanent && std::isfinite(permanent) && std::fabs(det) > bound) return det > 0 ? 1 : -1;
    return orient2d_exact(ax, ay, bx, by, cx, cy);
}

}  // namespace dualhex::geometry::exact
