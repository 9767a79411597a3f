// SPDX-License-Identifier: Apache-2.0
// The scalar Kalman update (Joseph form expanded for one sparse row) against
// the matrix Joseph form of the joint update of the same measurements.
#include <doctest/doctest.h>

#include <random>

#include <Eigen/Dense>
#include <pednav_navmath/kalman_update.hpp>

using namespace pednav::navmath;

TEST_CASE("kalman_scalar_update: two components one after the other give the joint Joseph-form update") {
    constexpr int N = 8;
    using Mat = Eigen::Matrix<double, N, N>;
    using Vec = Eigen::Matrix<double, N, 1>;
    std::mt19937 rng(11);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        Mat A;
        for (int i = 0; i < N; ++i)
            for (int j = 0; j < N; ++j) A(i, j) = g(rng);
        const Mat P0 = A * A.transpose() + 0.1 * Mat::Identity();
        // Two rows with four nonzero entries each (like a GNSS fix's), R = r I.
        const int idx0[4] = {0, 2, 4, 6}, idx1[4] = {1, 2, 4, 7};
        const double h0[4] = {1.0, g(rng), g(rng), 1.0}, h1[4] = {1.0, g(rng), g(rng), 1.0};
        const double r = 0.25, y0 = g(rng), y1 = g(rng);
        Eigen::Matrix<double, 2, N> H = Eigen::Matrix<double, 2, N>::Zero();
        for (int m = 0; m < 4; ++m) H(0, idx0[m]) = h0[m], H(1, idx1[m]) = h1[m];
        const Eigen::Matrix2d R = r * Eigen::Matrix2d::Identity();
        const Eigen::Matrix<double, N, 2> K = P0 * H.transpose() * (H * P0 * H.transpose() + R).inverse();
        const Vec dx_joint = K * Eigen::Vector2d(y0, y1);
        const Mat IKH = Mat::Identity() - K * H;
        const Mat P_joint = IKH * P0 * IKH.transpose() + K * R * K.transpose();

        Mat P = P0;
        Vec dx = Vec::Zero();
        CHECK(kalman_innovation_variance(P, idx0, h0, r) ==
              doctest::Approx((H.row(0) * P0 * H.row(0).transpose())(0, 0) + r));
        CHECK(kalman_scalar_update(P, dx, idx0, h0, y0, r) > 0);
        CHECK(kalman_scalar_update(P, dx, idx1, h1, y1, r) > 0);
        CHECK((dx - dx_joint).cwiseAbs().maxCoeff() < 1e-10 * (1.0 + dx_joint.cwiseAbs().maxCoeff()));
        CHECK((P - P_joint).cwiseAbs().maxCoeff() < 1e-10 * P0.cwiseAbs().maxCoeff());
        CHECK(P == P.transpose());  // exactly symmetric
    }
    // A measurement of no variance about a state of none changes nothing.
    Mat P = Mat::Zero();
    Vec dx = Vec::Zero();
    const int idx[1] = {3};
    const double h[1] = {1.0};
    CHECK(kalman_scalar_update(P, dx, idx, h, 1.0, 0.0) == 0.0);
    CHECK(dx.isZero());
}
