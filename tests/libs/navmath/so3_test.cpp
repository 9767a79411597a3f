// SPDX-License-Identifier: Apache-2.0
// Rotations: skew, Cayley, quaternion exp and log, unit-length products and rotations.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <utility>

#include <pednav_navmath/so3.hpp>

using namespace pednav::navmath;

TEST_CASE("skew matrix is the cross product (foot-imu-zupt-zaru-ekf eq. (9) as corrected)") {
    const Vec3 w(0.3, -1.2, 2.5), v(-0.7, 0.4, 1.1);
    CHECK((skew(w) * v - w.cross(v)).norm() < 1e-15);
    CHECK((skew(w) + skew(w).transpose()).norm() == 0.0);
}

TEST_CASE("Cayley transform is a rotation and matches the exponential to second order") {
    for (double a : {1e-3, 1e-2, 0.1}) {
        const Vec3 r = a * Vec3(0.3, -0.5, 0.8).normalized();
        const Mat3 c = cayley(r);
        CHECK((c * c.transpose() - Mat3::Identity()).norm() < 1e-14);
        const Mat3 e = quat_exp(r).toRotationMatrix();
        // The Pade (1,1) error is (|r|^3)/12.
        CHECK((c - e).norm() < a * a * a / 6.0 + 1e-15);
    }
}

TEST_CASE("quaternion exp and log are inverse, also near zero") {
    for (double a : {0.0, 1e-9, 1e-4, 0.5, 3.0}) {
        const Vec3 r = a * Vec3(-0.2, 0.9, 0.4).normalized();
        CHECK((quat_log(quat_exp(r)) - r).norm() < 1e-12);
        CHECK(std::abs(quat_exp(r).norm() - 1.0) < 1e-15);
    }
}

TEST_CASE("renormalize brings a product of unit quaternions back to unit length, and far-off ones exactly") {
    Quat q(0.3, -0.5, 0.7, 0.2);
    q.normalize();
    Quat near = q;
    near.coeffs() *= 1.0 + 3e-9;  // |q|^2 = 1 + 6e-9
    renormalize(near);
    CHECK(std::abs(near.squaredNorm() - 1.0) < 4e-16);
    CHECK(near.angularDistance(q) < 1e-15);
    Quat far(2.0, 0.0, 0.0, 0.0);
    renormalize(far);
    CHECK(far.w() == 1.0);
    Quat zero(0.0, 0.0, 0.0, 0.0);
    renormalize(zero);
    CHECK(zero.coeffs().cwiseAbs().maxCoeff() == 0.0);
    CHECK(unit_length_scale(std::nan("")) == 1.0);
}

TEST_CASE("rotate(q, v) is q.toRotationMatrix() * v bit for bit") {
    std::mt19937 rng(11);
    std::normal_distribution<double> n01(0.0, 1.0);
    int differ = 0;
    for (int k = 0; k < 1000; ++k) {
        const Quat q = Quat(n01(rng), n01(rng), n01(rng), n01(rng)).normalized();
        const Vec3 v(10 * n01(rng), 10 * n01(rng), 10 * n01(rng));
        const Mat3 R = q.toRotationMatrix();
        const Vec3 ref = R * v;
        differ += rotate(q, v) != ref;
    }
    CHECK(differ == 0);
}

TEST_CASE("quat_mul_unit is the Hamilton product at unit length, in either order, also from off-unit factors") {
    std::mt19937 rng(7);
    std::normal_distribution<double> n01(0.0, 1.0);
    double worst_product = 0, worst_norm = 0;
    for (int k = 0; k < 1000; ++k) {
        const Quat a = Quat(n01(rng), n01(rng), n01(rng), n01(rng)).normalized();
        const Quat b = quat_exp(0.01 * Vec3(n01(rng), n01(rng), n01(rng)));
        for (const auto& [l, r] : {std::pair<Quat, Quat>{a, b}, std::pair<Quat, Quat>{b, a}}) {
            const Quat ref = (l * r).normalized();
            const Quat got = quat_mul_unit(l, r);
            worst_product = std::max(worst_product, (got.coeffs() - ref.coeffs()).cwiseAbs().maxCoeff());
            worst_norm = std::max(worst_norm, std::abs(got.squaredNorm() - 1.0));
        }
    }
    CHECK(worst_product < 1e-15);
    CHECK(worst_norm < 1e-15);
    // Far from unit length: normalized exactly.
    const Quat big = quat_mul_unit(Quat(2.0, 0.0, 0.0, 0.0), Quat(0.0, 0.0, 3.0, 0.0));
    CHECK(big.y() == 1.0);
    CHECK(big.w() == 0.0);
    // A zero product stays zero (no division by its norm).
    const Quat zero = quat_mul_unit(Quat(0.0, 0.0, 0.0, 0.0), Quat(0.6, 0.0, 0.8, 0.0));
    CHECK(zero.coeffs().cwiseAbs().maxCoeff() == 0.0);
}
