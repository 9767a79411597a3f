// SPDX-License-Identifier: Apache-2.0
#include "pednav_zupt_ins/ekf15_dense.hpp"

#include <Eigen/LU>

namespace pednav::zupt_ins {

using navmath::skew;

void Ekf15Dense::reset_covariance(const double* diag) {
    P_.setZero();
    x_.setZero();
    deferred_M_.setIdentity();
    deferred_Q_.setZero();
    deferred_s_ = 0;
    if (diag)
        for (int i = 0; i < N; ++i) P_(i, i) = diag[i];
}

Ekf15Dense::MatN Ekf15Dense::transition(double dt, const Mat3& R, const Vec3& f) {
    // Phi = I + A dt with the continuous error dynamics of ekf15.hpp.
    MatN Phi = MatN::Identity();
    Phi.block<3, 3>(ATT, BG) = -R * dt;
    Phi.block<3, 3>(POS, VEL) = Mat3::Identity() * dt;
    Phi.block<3, 3>(VEL, ATT) = -skew(f) * dt;
    Phi.block<3, 3>(VEL, BA) = -R * dt;
    return Phi;
}

Ekf15Dense::VecN Ekf15Dense::noise(double dt, const Noise& q) {
    const Ekf15::NoiseVariance v = Ekf15::NoiseVariance::over(q, dt);
    VecN d = VecN::Zero();
    for (int i = 0; i < 3; ++i) {
        d(ATT + i) = v.att_rad2;
        d(BG + i) = v.gyro_bias_rad2ps2;
        d(VEL + i) = v.vel_m2ps2;
        d(BA + i) = v.accel_bias_m2ps4;
    }
    return d;
}

void Ekf15Dense::propagate(double dt, const Mat3& R, const Vec3& f, const Noise& q) {
    apply_deferred();
    const MatN Phi = transition(dt, R, f);
    const MatN Q = noise(dt, q).asDiagonal();
    P_ = Phi * P_ * Phi.transpose() + Q;
}

void Ekf15Dense::defer_propagation(double dt, const Mat3& R, const Vec3& f, const Noise& q) {
    deferred_M_ = (transition(dt, R, f) * deferred_M_).eval();
    deferred_Q_ += noise(dt, q);
    deferred_s_ += dt;
}

void Ekf15Dense::apply_deferred() {
    if (!(deferred_s_ > 0)) return;
    const MatN half_Q = (0.5 * deferred_Q_).asDiagonal();
    P_ = deferred_M_ * (P_ + half_Q) * deferred_M_.transpose() + half_Q;
    deferred_M_.setIdentity();
    deferred_Q_.setZero();
    deferred_s_ = 0;
}

template <int M>
void Ekf15Dense::update(int i0, const double* z, const double* var, uint32_t hold_mask) {
    apply_deferred();
    Eigen::Matrix<double, M, N> H = Eigen::Matrix<double, M, N>::Zero();
    Eigen::Matrix<double, M, M> Rm = Eigen::Matrix<double, M, M>::Zero();
    Eigen::Matrix<double, M, 1> zm;
    for (int j = 0; j < M; ++j) {
        H(j, i0 + j) = 1.0;
        Rm(j, j) = var[j];
        zm(j) = z[j];
    }
    const Eigen::Matrix<double, M, M> S = H * P_ * H.transpose() + Rm;
    if (!(S.determinant() > 0)) return;
    Eigen::Matrix<double, N, M> K = P_ * H.transpose() * S.inverse();
    for (int k = 0; k < N; ++k)
        if (hold_mask & (1u << k)) K.row(k).setZero();
    x_ += K * (zm - H * x_);
    const MatN IKH = MatN::Identity() - K * H;
    if (joseph_ || hold_mask) P_ = IKH * P_ * IKH.transpose() + K * Rm * K.transpose();
    else P_ = IKH * P_;
}

void Ekf15Dense::update_scalar(int i, double z, double var) { update<1>(i, &z, &var); }

void Ekf15Dense::update_block3(int i0, const double z[3], const double var[3], uint32_t hold_mask) {
    update<3>(i0, z, var, hold_mask);
}

}  // namespace pednav::zupt_ins
