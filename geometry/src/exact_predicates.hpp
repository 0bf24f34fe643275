#pragma once
// Exact orientation predicates on double coordinates: a floating-point evaluation whose
// error bound (Shewchuk's static bound for the plain determinant) decides the sign when it
// can, else the determinant in exact rational arithmetic (GMP; every double is a dyadic
// rational, so the conversion is exact; scaled to integers, mpz, when the exponents allow).
// The sign returned is always the true sign.
#include <Eigen/Core>

namespace dualhex::geometry::exact {

/// Sign of det[a-d; b-d; c-d]: > 0 iff d lies below the plane through a, b, c (seen so
/// that a, b, c turn counter-clockwise), 0 iff coplanar.
[[nodiscard]] int orient3d(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                           const Eigen::Vector3d& d);

/// Sign of det[a-c; b-c] of the 2D points (x, y): > 0 iff a, b, c turn counter-clockwise.
[[nodiscard]] int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace dualhex::geometry::exact
