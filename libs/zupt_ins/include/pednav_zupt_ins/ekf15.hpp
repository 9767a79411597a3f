// SPDX-License-Identifier: Apache-2.0
// 15-state error-state Kalman filter covariance and estimate, hand-written
// for speed: block-structured transition, selection measurements as scalar
// Joseph-form updates, symmetric by construction, no allocation. Only the
// upper triangle of P is kept up to date; propagate() mirrors it once into the
// lower triangle (the rows it reads whole), updates write upper rows only.
//
// Error state (foot-imu-zupt-zaru-ekf eq. (24)), all "true minus estimate":
//   x = [phi (ENU attitude error, rad), dbg (gyro bias, rad/s, body),
//        dp (position, m, ENU), dv (velocity, m/s, ENU), dba (accel bias, m/s^2, body)]
// with R_true = exp(skew(phi)) R_est, bias_true = bias_est + dbg, etc.
// Continuous error dynamics (the sign convention of eq. (26) in this form):
//   phi' = -R dbg,  dp' = dv,  dv' = -skew(f_enu) phi - R dba
// discretised as Phi = I + A dt (eq. (25)-(26)).
#pragma once

#include <cstdint>
#include <cstring>

#include <pednav_navmath/so3.hpp>

namespace pednav::zupt_ins {

using navmath::Mat3;
using navmath::Quat;
using navmath::Vec3;

class Ekf15 {
public:
    static constexpr int N = 15;
    static constexpr int NP = 16;  // row stride: rows padded to 16 doubles (aligned, even length)
    static constexpr int ATT = 0, BG = 3, POS = 6, VEL = 9, BA = 12;

    struct Noise {
        double gyro_psd = 0;     // (rad/s)^2 / Hz: angle random walk density squared
        double accel_psd = 0;    // (m/s^2)^2 / Hz: velocity random walk density squared
        double gyro_bias_psd = 0;   // (rad/s)^2 / s
        double accel_bias_psd = 0;  // (m/s^2)^2 / s
    };

    // The process noise variances that Noise adds over an interval (Q's
    // diagonal, isotropic per block).
    struct NoiseVariance {
        double att_rad2 = 0;
        double gyro_bias_rad2ps2 = 0;
        double vel_m2ps2 = 0;
        double accel_bias_m2ps4 = 0;
        static NoiseVariance over(const Noise& q, double dt_s) {
            return {q.gyro_psd * dt_s, q.gyro_bias_psd * dt_s, q.accel_psd * dt_s, q.accel_bias_psd * dt_s};
        }
        NoiseVariance& operator+=(const NoiseVariance& o) {
            att_rad2 += o.att_rad2;
            gyro_bias_rad2ps2 += o.gyro_bias_rad2ps2;
            vel_m2ps2 += o.vel_m2ps2;
            accel_bias_m2ps4 += o.accel_bias_m2ps4;
            return *this;
        }
        NoiseVariance scaled(double k) const {
            return {k * att_rad2, k * gyro_bias_rad2ps2, k * vel_m2ps2, k * accel_bias_m2ps4};
        }
    };

    Ekf15() { reset_covariance(nullptr); }

    // Covariance update form: Joseph (eq. (33), default; robust to a gain that
    // is not exactly optimal) or P - K H P (the same for the optimal gain, a
    // third of the arithmetic). Both keep P exactly symmetric.
    void set_joseph(bool joseph) { joseph_ = joseph; }

    // Diagonal initial covariance (variances in the state's units).
    void reset_covariance(const double* diag15);

    // P <- Phi P Phi^T + Q for one interval (foot-imu-zupt-zaru-ekf eq. (32)).
    // A deferred transition (below) is applied first.
    void propagate(double dt, const Mat3& r_enu_from_body, const Vec3& f_enu, const Noise& q);

    // Intervals without a measurement (the swing) need P only at their end:
    // their transitions are multiplied into one, M = Phi_k ... Phi_1 (its
    // block structure kept, SwingTransition), and apply_deferred() then
    // applies P <- M (P + Q/2) M^T + Q/2 once, with Q the summed process
    // noise split between both ends (trapezoidal; all of it at the end is a
    // first-order placement). Until then P() is the covariance of the last
    // applied step. propagate() and the updates apply a deferred transition
    // first.
    void defer_propagation(double dt, const Mat3& r_enu_from_body, const Vec3& f_enu, const Noise& q) {
        deferred_.add(dt, r_enu_from_body, f_enu, q);
    }
    double deferred_s() const { return deferred_.t_s; }
    void apply_deferred() {
        if (deferred_.t_s > 0) apply_transition();
    }

    // Scalar measurement z = x[i] + noise(var): Kalman gain (eq. (31)), state
    // update (eq. (30)) and Joseph-form covariance (eq. (33)) with H = e_i.
    void update_scalar(int i, double z, double var);

    // Three measurements z = x[i0..i0+2] + noise (diagonal variances var) as
    // one block: the same Joseph form with H selecting three states, one pass
    // over P instead of three. States whose bit is set in hold_mask keep
    // their estimate (their rows of K are zero, a "consider" update): the
    // Joseph form keeps P right for that gain, so it is used then whatever
    // set_joseph() says.
    void update_block3(int i0, const double z[3], const double var[3], uint32_t hold_mask = 0);

    const double* x() const { return x_; }
    double* x() { return x_; }
    double P(int i, int j) const { return i <= j ? P_[i][j] : P_[j][i]; }
    void clear_state() { std::memset(x_, 0, sizeof x_); }

private:
    // E = M - I for M = Phi_k ... Phi_1 with every Phi = I + G as in
    // propagate(): nonzero in rows ATT, POS, VEL only. Per interval,
    // M <- (I + G) M gives E <- E + G + G E, with G E nonzero in
    // (POS, ATT|BG|BA) = dt E(VEL, .) and (VEL, BG) = -skew(f) dt E(ATT, BG):
    //   E(ATT, BG) = E(VEL, BA) = C     C      = -sum R dt            (s)
    //   E(VEL, ATT) = -skew(dv_mps)     dv_mps = sum f dt             (m/s)
    //   E(VEL, BG)  = VB                VB    += -skew(f dt) C        (m)
    //   E(POS, ATT) = -skew(dp_m)       dp_m  += dt dv_mps            (m)
    //   E(POS, BG)  = PB                PB    += dt VB                (m s)
    //   E(POS, VEL) = t_s I             t_s    = sum dt               (s)
    //   E(POS, BA)  = PE                PE    += dt C                 (s^2)
    // (the POS blocks with the values before the interval's own terms):
    // eight nonzero blocks, seven distinct. dv_mps and dp_m are the velocity
    // and position that the specific force alone adds over the swing.
    // Rows padded to four (aligned, the padding zero).
    struct SwingTransition {
        alignas(32) double C[3][4] = {};
        alignas(32) double VB[3][4] = {};
        alignas(32) double PB[3][4] = {};
        alignas(32) double PE[3][4] = {};
        alignas(32) double dv_mps[4] = {};
        alignas(32) double dp_m[4] = {};
        double t_s = 0;
        NoiseVariance q_sum;  // summed over the intervals
        void clear() { *this = SwingTransition(); }
        void add(double dt, const Mat3& R, const Vec3& f, const Noise& q);
    };
    void apply_transition();
    void add_noise(const NoiseVariance& q);

    // Entry (a, b) with a <= b holds P_ab; entries below the diagonal are
    // stale except right after mirror_lower(). Column 15 is padding, zero.
    void mirror_lower();
    // Column i of P (rows 0..14) read from the upper triangle; out[15] = 0.
    // `out` is 32-byte aligned: the row part is copied in aligned chunks of
    // four from i & ~3, and the entries before i then overwritten.
    void column_inline(int i, double* out) const {
        for (int k = i & ~3; k < NP; k += 4)
            for (int l = 0; l < 4; ++l) out[k + l] = P_[i][k + l];  // P_[i][15] is the zero padding
        for (int k = 0; k < i; ++k) out[k] = P_[k][i];
    }
    void scalar_kernel(int i, double z, double var);
    void block3_kernel(int i0, const double z[3], const double var[3], uint32_t hold_mask);

    alignas(64) double P_[N][NP];
    alignas(32) double x_[NP];  // x_[15] is padding, zero
    SwingTransition deferred_;
    bool joseph_ = true;
};

}  // namespace pednav::zupt_ins
