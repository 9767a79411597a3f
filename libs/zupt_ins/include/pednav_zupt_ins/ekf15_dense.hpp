// SPDX-License-Identifier: Apache-2.0
// The same 15-state error-state Kalman filter as ekf15.hpp, written the
// textbook way with dense fixed-size Eigen matrices: a full 15 x 15 Phi,
// P <- Phi P Phi^T + Q, a dense H, K = P H^T S^-1 and the Joseph form
// (I - K H) P (I - K H)^T + K R K^T (foot-imu-zupt-zaru-ekf eq. (25)-(33)).
// A reference for the hand-written kernels (the whole foot pipeline must give
// the same track with either, to round-off) and a yardstick for the speed
// benchmark; the plugin org.pednav.foot.ekf15.dense runs the foot INS on it.
#pragma once

#include "ekf15.hpp"

namespace pednav::zupt_ins {

class Ekf15Dense {
public:
    static constexpr int N = Ekf15::N;
    static constexpr int ATT = Ekf15::ATT, BG = Ekf15::BG, POS = Ekf15::POS, VEL = Ekf15::VEL, BA = Ekf15::BA;
    using Noise = Ekf15::Noise;
    using MatN = Eigen::Matrix<double, N, N>;
    using VecN = Eigen::Matrix<double, N, 1>;

    Ekf15Dense() { reset_covariance(nullptr); }

    void set_joseph(bool joseph) { joseph_ = joseph; }
    void reset_covariance(const double* diag15);
    void propagate(double dt, const Mat3& r_enu_from_body, const Vec3& f_enu, const Noise& q);
    // As Ekf15: M <- Phi M over the deferred intervals (a dense product here),
    // then P <- M (P + Q/2) M^T + Q/2.
    void defer_propagation(double dt, const Mat3& r_enu_from_body, const Vec3& f_enu, const Noise& q);
    double deferred_s() const { return deferred_s_; }
    void apply_deferred();
    void update_scalar(int i, double z, double var);
    void update_block3(int i0, const double z[3], const double var[3], uint32_t hold_mask = 0);

    const double* x() const { return x_.data(); }
    double* x() { return x_.data(); }
    double P(int i, int j) const { return P_(i, j); }
    void clear_state() { x_.setZero(); }

private:
    // z = H x + noise with H selecting the M states from i0.
    template <int M>
    void update(int i0, const double* z, const double* var, uint32_t hold_mask = 0);

    static MatN transition(double dt, const Mat3& R, const Vec3& f);
    static VecN noise(double dt, const Noise& q);

    MatN P_;
    VecN x_;
    MatN deferred_M_ = MatN::Identity();
    VecN deferred_Q_ = VecN::Zero();
    double deferred_s_ = 0;
    bool joseph_ = true;
};

}  // namespace pednav::zupt_ins
