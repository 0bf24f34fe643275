// The optimiser's barrier energy (mesher/src/hex_energy.hpp, internal): the closed-form
// per-vertex gradient and Hessian (hex_newton) against central differences of the energy
// and of its analytic gradient, on a valid, a sheared and an inverted hex, for a large and
// a small eps; and a wrong Hessian (a sign flipped) is caught by the same comparison.
#include <gtest/gtest.h>

#include "../mesher/src/hex_energy.hpp"
#include "test_geometry_hex_block.hpp"

using namespace dualhex;
using dualhex::mesher::detail::BarrierEnergy;

namespace {

struct Derivatives {
    double value = 0;
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
};

Derivatives closed_form(const BarrierEnergy& e, const geometry::HexMesh& m, int v, const Eigen::Vector3d& x) {
    Derivatives d;
    d.value = e.hex_newton(m, 0, v, x, d.gradient, d.hessian);
    return d;
}

// Central differences: the gradient from the energy, the Hessian from hex()'s gradient.
Derivatives numerical(const BarrierEnergy& e, const geometry::HexMesh& m, int v, const Eigen::Vector3d& x, double h) {
    Derivatives d;
    d.value = e.hex(m, 0, v, x, nullptr);
    for (int a = 0; a < 3; ++a) {
        Eigen::Vector3d dx = Eigen::Vector3d::Zero();
        dx[a] = h;
        Eigen::Vector3d gp = Eigen::Vector3d::Zero(), gm = Eigen::Vector3d::Zero();
        d.gradient[a] = (e.hex(m, 0, v, x + dx, &gp) - e.hex(m, 0, v, x - dx, &gm)) / (2 * h);
        d.hessian.col(a) = (gp - gm) / (2 * h);
    }
    return d;
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / (1 + b.norm()); }

}  // namespace

TEST(MesherHexEnergy, ClosedFormHessianMatchesDifferences) {
    const geometry::HexMesh cube = geometry_test::hex_block(1, 1, 1).mesh;
    const Eigen::Vector3d moves[] = {{0.1, -0.05, 0.2}, {0.4, 0.3, -0.3}, {-0.7, -0.6, -0.8}};  // the last inverts
    for (const Eigen::Vector3d& move : moves)
        for (double eps : {0.5, 1e-3})
            for (int v : {0, 6}) {
                geometry::HexMesh m = cube;
                m.points[7] += Eigen::Vector3d(0.1, -0.2, 0.05);  // a hex that is not a cube
                BarrierEnergy e(m);
                e.eps = eps;
                const Eigen::Vector3d x = m.points[static_cast<std::size_t>(v)] + move;
                const Derivatives exact = closed_form(e, m, v, x), approx = numerical(e, m, v, x, 1e-6);
                EXPECT_EQ(exact.value, approx.value) << "eps " << eps << " v " << v;  // the same sum, bit for bit
                EXPECT_LT(relative(exact.gradient, approx.gradient), 1e-5) << "eps " << eps << " v " << v;
                EXPECT_LT(relative(exact.hessian, approx.hessian), 1e-4) << "eps " << eps << " v " << v;
                EXPECT_LT(relative(exact.hessian, exact.hessian.transpose()), 1e-12);
                // The comparison can fail: a Hessian with one term's sign flipped is far off.
                Eigen::Matrix3d wrong = exact.hessian;
                wrong(0, 1) = -wrong(0, 1);
                wrong(1, 0) = -wrong(1, 0);
                if (std::abs(exact.hessian(0, 1)) > 1e-3) EXPECT_GT(relative(wrong, approx.hessian), 1e-4);
            }
}
