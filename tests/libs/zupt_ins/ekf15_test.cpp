// SPDX-License-Identifier: Apache-2.0
// The 15-state error-state EKF's covariance algebra against the dense textbook
// forms (foot-imu-zupt-zaru-ekf eq. (25)-(33)).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include <pednav_navmath/so3.hpp>
#include <pednav_zupt_ins/ekf15.hpp>

#include "../test_attitude.hpp"

using namespace pednav::zupt_ins;
using pednav::test::attitude;
using pednav::navmath::skew;

namespace {
using MatN = Eigen::Matrix<double, 15, 15>;

// The textbook transition and process noise of one interval, dense
// (foot-imu-zupt-zaru-ekf eq. (25)-(26), (32)).
MatN dense_transition(double dt, const Mat3& R, const Vec3& f) {
    MatN Phi = MatN::Identity();
    Phi.block<3, 3>(Ekf15::ATT, Ekf15::BG) = -R * dt;
    Phi.block<3, 3>(Ekf15::POS, Ekf15::VEL) = Mat3::Identity() * dt;
    Phi.block<3, 3>(Ekf15::VEL, Ekf15::ATT) = -skew(f) * dt;
    Phi.block<3, 3>(Ekf15::VEL, Ekf15::BA) = -R * dt;
    return Phi;
}

MatN dense_noise(double dt, const Ekf15::Noise& q) {
    MatN Q = MatN::Zero();
    for (int i = 0; i < 3; ++i) {
        Q(Ekf15::ATT + i, Ekf15::ATT + i) = q.gyro_psd * dt;
        Q(Ekf15::BG + i, Ekf15::BG + i) = q.gyro_bias_psd * dt;
        Q(Ekf15::VEL + i, Ekf15::VEL + i) = q.accel_psd * dt;
        Q(Ekf15::BA + i, Ekf15::BA + i) = q.accel_bias_psd * dt;
    }
    return Q;
}

// A filter whose covariance has every correlation: 60 steps at changing
// attitudes and specific forces, then one velocity update.
Ekf15 correlated_filter(const Ekf15::Noise& q) {
    Ekf15 ekf;
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.01 * (i + 1);
    ekf.reset_covariance(d);
    for (int k = 0; k < 60; ++k)
        ekf.propagate(0.005, attitude(0.05 * k, 0.3 * std::sin(0.2 * k), -0.2), Vec3(3.0 * std::cos(0.3 * k), -2.0, 9.81), q);
    const double z[3] = {0.01, -0.02, 0.0}, var[3] = {1e-4, 1e-4, 1e-4};
    ekf.update_block3(Ekf15::VEL, z, var);
    return ekf;
}

MatN covariance_of(const Ekf15& e) {
    MatN P;
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) P(i, j) = e.P(i, j);
    return P;
}
}  // namespace

TEST_CASE("EKF propagation matches the dense Phi P Phi^T + Q, and the Joseph update the textbook one") {
    Ekf15 ekf;
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.01 * (i + 1);
    ekf.reset_covariance(d);
    Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    const Mat3 R = attitude(0.4, 0.3, -0.2);
    const Vec3 f(1.0, -2.0, 9.81);
    const double dt = 0.005;
    for (int k = 0; k < 200; ++k) ekf.propagate(dt, R, f, q);
    // One more step against the dense reference.
    const MatN P0 = covariance_of(ekf), Phi = dense_transition(dt, R, f);
    const MatN P1_ref = Phi * P0 * Phi.transpose() + dense_noise(dt, q);
    ekf.propagate(dt, R, f, q);
    double max_prop_diff = 0;
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) max_prop_diff = std::max(max_prop_diff, std::abs(ekf.P(i, j) - P1_ref(i, j)));
    CHECK(max_prop_diff < 1e-12);
    // Textbook update for H = e_9 on a copy.
    const MatN P = covariance_of(ekf);
    const double r = 1e-4;
    const Eigen::Matrix<double, 15, 1> K = P.col(9) / (P(9, 9) + r);
    const Eigen::Matrix<double, 15, 15> P_ref = P - K * P.row(9);
    ekf.update_scalar(9, 0.1, r);
    double max_diff = 0;
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) max_diff = std::max(max_diff, std::abs(ekf.P(i, j) - P_ref(i, j)));
    CHECK(max_diff < 1e-12);
    CHECK(std::abs(ekf.x()[9] - K(9) * 0.1) < 1e-15);
    // Positive semi-definite.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 15, 15>> es(P_ref);
    CHECK(es.eigenvalues().minCoeff() > -1e-12);
}

TEST_CASE("EKF block update of three selected states equals three scalar updates") {
    Ekf15 a, b;
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.02 * (i + 1);
    a.reset_covariance(d);
    Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    const Mat3 R = attitude(1.1, -0.2, 0.4);
    for (int k = 0; k < 100; ++k) a.propagate(0.01, R, Vec3(2.0, 1.0, 9.0), q);
    b = a;
    const double z[3] = {0.1, -0.05, 0.02}, var[3] = {1e-4, 2e-4, 3e-4};
    a.update_block3(Ekf15::VEL, z, var);
    for (int i = 0; i < 3; ++i) b.update_scalar(Ekf15::VEL + i, z[i], var[i]);
    double dp = 0, dx = 0;
    for (int i = 0; i < 15; ++i) {
        dx = std::max(dx, std::abs(a.x()[i] - b.x()[i]));
        for (int j = 0; j < 15; ++j) {
            dp = std::max(dp, std::abs(a.P(i, j) - b.P(i, j)));
        }
    }
    CHECK(dx < 1e-12);
    CHECK(dp < 1e-12);
}

TEST_CASE("EKF block update that holds some states equals the textbook Joseph form with those gain rows zero") {
    const Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    Ekf15 ekf = correlated_filter(q);
    ekf.clear_state();
    const MatN P = covariance_of(ekf);
    const double z[3] = {0.003, -0.002, 0.001}, var[3] = {4e-4, 4e-4, 4e-4};
    const uint32_t hold = 7u << Ekf15::POS;
    // Textbook: K = P H^T S^-1 with the held rows zeroed, Joseph form.
    Eigen::Matrix<double, 3, 15> H = Eigen::Matrix<double, 3, 15>::Zero();
    for (int j = 0; j < 3; ++j) H(j, Ekf15::BG + j) = 1.0;
    const Mat3 S = H * P * H.transpose() + Mat3(Vec3(var[0], var[1], var[2]).asDiagonal());
    Eigen::Matrix<double, 15, 3> K = P * H.transpose() * S.inverse();
    K.middleRows<3>(Ekf15::POS).setZero();
    const MatN IKH = MatN::Identity() - K * H;
    const MatN P_ref = IKH * P * IKH.transpose() + K * Mat3(Vec3(var[0], var[1], var[2]).asDiagonal()) * K.transpose();
    const Eigen::Matrix<double, 15, 1> x_ref = K * Vec3(z[0], z[1], z[2]);
    for (bool joseph : {true, false}) {  // a held state always takes the Joseph form
        CAPTURE(joseph);
        Ekf15 e = ekf;
        e.set_joseph(joseph);
        e.update_block3(Ekf15::BG, z, var, hold);
        double dp = 0, dx = 0;
        for (int i = 0; i < 15; ++i) {
            dx = std::max(dx, std::abs(e.x()[i] - x_ref(i)));
            for (int j = 0; j < 15; ++j) dp = std::max(dp, std::abs(e.P(i, j) - P_ref(i, j)));
        }
        CHECK(dp < 1e-14);
        CHECK(dx < 1e-16);
        for (int i = 0; i < 3; ++i) CHECK(e.x()[Ekf15::POS + i] == 0.0);
    }
    // Holding costs information: the held update leaves more variance than the optimal one.
    Ekf15 opt = ekf;
    opt.update_block3(Ekf15::BG, z, var);
    Ekf15 held = ekf;
    held.update_block3(Ekf15::BG, z, var, hold);
    for (int i = 0; i < 15; ++i) CHECK(held.P(i, i) >= opt.P(i, i) - 1e-15);
    CHECK(held.P(Ekf15::POS, Ekf15::POS) > opt.P(Ekf15::POS, Ekf15::POS));
}

TEST_CASE("EKF deferred swing propagation: the structured product equals the dense one, noise split at both ends") {
    const auto max_abs = [](const MatN& m) { return m.cwiseAbs().maxCoeff(); };
    const Ekf15::Noise q{1e-4, 1e-3, 1e-8, 1e-6};
    Ekf15 ekf = correlated_filter(q);
    const MatN P0 = covariance_of(ekf);

    // A swing: 24 intervals of uneven length, the foot pitching through 100
    // degrees and turning, specific force up to 3 g.
    MatN M = MatN::Identity(), Qsum = MatN::Zero(), P_each = P0;
    Ekf15 per_step = ekf;
    double t_s = 0;
    for (int k = 0; k < 24; ++k) {
        const double dt = 0.004 + 0.001 * (k % 3);
        const Mat3 R = attitude(0.4 + 0.02 * k, -0.8 + 0.075 * k, 0.1 * std::sin(0.5 * k));
        const Vec3 f(25.0 * std::sin(0.3 * k), 4.0 * std::cos(0.7 * k), 9.81 + 15.0 * std::cos(0.25 * k));
        const MatN Phi = dense_transition(dt, R, f), Q = dense_noise(dt, q);
        M = Phi * M;
        Qsum += Q;
        P_each = Phi * P_each * Phi.transpose() + Q;
        ekf.defer_propagation(dt, R, f, q);
        per_step.propagate(dt, R, f, q);
        t_s += dt;
    }
    CHECK(ekf.deferred_s() == doctest::Approx(t_s).epsilon(1e-12));
    // Until applied, P is the covariance before the swing.
    CHECK(max_abs(covariance_of(ekf) - P0) == 0.0);

    // The updates and propagate() apply the deferred transition first;
    // reset_covariance() drops it.
    Ekf15 updated = ekf, block_updated = ekf, propagated = ekf, reset = ekf;
    ekf.apply_deferred();
    CHECK(ekf.deferred_s() == 0.0);
    const MatN P_def = covariance_of(ekf);
    const MatN P_ref = M * (P0 + 0.5 * Qsum) * M.transpose() + 0.5 * Qsum;
    CHECK(max_abs(P_def - P_ref) < 1e-12 * max_abs(P_ref));
    CHECK(max_abs(P_def - P_def.transpose()) == 0.0);

    // Against propagating every interval: the one product is exact but for
    // where the noise enters; half at each end is closer than all at the end.
    CHECK(max_abs(covariance_of(per_step) - P_each) < 1e-12 * max_abs(P_each));
    // Errors relative to the noise's share of the swing's covariance (this
    // swing of 0.12 s, a little longer than the preset interval, at up to
    // 3 g: 4.6 % and 10 %; the rest of the covariance is exact).
    const MatN noise_part = P_each - M * P0 * M.transpose();
    const MatN P_end = M * P0 * M.transpose() + Qsum;
    const double err_split = (P_def - P_each).norm() / noise_part.norm();
    const double err_end = (P_end - P_each).norm() / noise_part.norm();
    MESSAGE("deferred vs every interval, relative to the noise's share: noise split " << err_split
            << ", noise at the end " << err_end);
    CHECK(err_split < 0.06);
    CHECK(err_split < 0.6 * err_end);

    const auto same = [&](const Ekf15& a, const Ekf15& b) {
        CHECK(a.deferred_s() == 0.0);
        CHECK(max_abs(covariance_of(a) - covariance_of(b)) == 0.0);
        for (int i = 0; i < 15; ++i) CHECK(a.x()[i] == b.x()[i]);
    };
    Ekf15 applied = ekf;
    const double zv = 0.05;
    updated.update_scalar(Ekf15::VEL, zv, 1e-4);
    applied.update_scalar(Ekf15::VEL, zv, 1e-4);
    same(updated, applied);
    const double z3[3] = {0.02, -0.01, 0.005}, var3[3] = {1e-4, 2e-4, 3e-4};
    applied = ekf;
    block_updated.update_block3(Ekf15::BG, z3, var3);
    applied.update_block3(Ekf15::BG, z3, var3);
    same(block_updated, applied);
    applied = ekf;
    const Mat3 R1 = attitude(0.9, 0.1, 0.05);
    const Vec3 f1(0.3, -0.2, 9.8);
    propagated.propagate(0.005, R1, f1, q);
    applied.propagate(0.005, R1, f1, q);
    same(propagated, applied);
    double d[15];
    for (int i = 0; i < 15; ++i) d[i] = 0.02 * (i + 1);
    Ekf15 fresh;
    fresh.reset_covariance(d);
    reset.reset_covariance(d);
    reset.propagate(0.005, R1, f1, q);
    fresh.propagate(0.005, R1, f1, q);
    same(reset, fresh);
}
