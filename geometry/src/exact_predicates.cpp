#include "exact_predicates.hpp"

#include <cmath>

#include <gmpxx.h>

namespace dualhex::geometry::exact {

namespace {

// Half an ulp of 1: the relative rounding error of one double operation.
constexpr double kEps = 1.0 / 9007199254740992.0;  // 2^-53
// Below this permanent, products may have lost bits to underflow and the relative error
// bounds no longer hold: decide exactly.
constexpr double kTinyPermanent = 1e-250;

int sign(const mpq_class& v) { return sgn(v); }

int orient3d_exact(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                   const Eigen::Vector3d& d) {
    mpq_class m[3][3];
    const Eigen::Vector3d* rows[3] = {&a, &b, &c};
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[r][k] = mpq_class((*rows[r])[k]) - mpq_class(d[k]);
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign(det);
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
    const mpq_class det_q = (mpq_class(ax) - mpq_class(cx)) * (mpq_class(by) - mpq_class(cy)) -
                            (mpq_class(ay) - mpq_class(cy)) * (mpq_class(bx) - mpq_class(cx));
    return sign(det_q);
}

}  // namespace dualhex::geometry::exact
