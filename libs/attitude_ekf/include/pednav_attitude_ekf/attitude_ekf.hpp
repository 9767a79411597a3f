// SPDX-License-Identifier: Apache-2.0
// Attitude of a body-worn IMU (waist paper, sec. 4.1-4.3): quaternion
// strapdown integration with a 9-state error-state EKF
//   dx = [dphi (ENU, rad), dbg (body, rad/s), dba (body, m/s^2)]   (eq. 4.8)
// (and the two coefficients of the magnetometer's compass deviation, below)
// with the errors defined as true minus estimated: R_true = (I + [dphi x]) R,
// b_true = b + db. Closed loop: every update is folded into the quaternion
// and the biases, and dx returns to 0.
//
// Propagation per IMU sample (eq. 4.2-4.5): w = w_m - bg, q <- q (x) exp(w dt)
// (eq. 4.4's rotation quaternion), and eq. (4.9)-(4.10) with the sign of this
// error definition: dphi' = dphi - dt R dbg, so
//   Phi = [[I, -dt R, 0], [0, I, 0], [0, 0, I]],  Q = diag(sg^2 dt, sbg^2 dt, sba^2 dt).
// Updates (replacing eq. 4.11-4.13, whose yaw observation comes from
// gyrocompassing, which a MEMS gyro cannot do: ERRATA.md):
//   gravity: the mean specific force in ENU over gravity_update_s,
//     f = R (a_m - ba), has no horizontal part on average (standing or
//     walking at a steady pace): y = [f_E, f_N] = H dx + v,
//     H = [[0, -g, 0, 0, R_E], [g, 0, 0, 0, R_N]] (R_E, R_N: rows of the
//     window's mean R), sd gravity_sd_quiet_mps2 when |a| is quiet over the
//     window, gravity_sd_moving_mps2 otherwise: roll and pitch;
//   still: a window with |w| and |a| still: y = mean w_m - bg = dbg + v: gyro bias;
//   magnetometer, while navmath::MagneticFieldGate accepts the reading:
//     y = wrap(psi_mag + declination - psi - B sin psi - C cos psi)
//       = -dphi_U + sin psi dB + cos psi dC + v
//     (heading is clockwise, dphi_U counter-clockwise), rejected beyond
//     mag_gate_chi2 (a disturbance that keeps the strength and dip) unless
//     mag_max_rejections in a row: then the field resets the yaw.
//     B sin psi + C cos psi is the compass deviation of a hard-iron field
//     (the sensor's own magnetisation, fixed in its frame): with the body
//     level axes h (x projected level) and l (left of h), a bias b adds
//     (b.h, b.l) to the horizontal field B_h (cos psi, sin psi) seen along
//     them, and atan2 turns that into psi + (b.l cos psi - b.h sin psi) / B_h
//     to first order: the semicircular deviation B = -b.h / B_h,
//     C = b.l / B_h of compass adjustment, constant while the sensor's tilt
//     is. Its constant part is the heading's own error; B and C become
//     observable against the gyro as the walker turns (states dB, dC, P0
//     mag_deviation_sd_rad, 0 = not estimated).
// Error state with the deviation: dx = [dphi, dbg, dba, dB, dC]; B and C
// are constants with a random walk (Phi's block is I) and enter only the
// magnetometer's H.
// The correction is q <- exp(dphi) (x) q in ENU (the left-multiplied form of
// eq. 4.6-4.7), bg += dbg, ba += dba, (B, C) += (dB, dC).
//
// Initial attitude: roll and pitch from the mean specific force of the first
// still period (or of the first align_timeout_s), the initial gyro bias from
// its mean rate; yaw from the magnetometer when the gate accepts it, else
// initial_heading_deg. Until the magnetometer or the app gives the yaw, a
// GNSS course (speed at least gnss_course_min_speed_mps) sets it once.
#pragma once

#include <cstdint>

#include <Eigen/Core>
#include <pednav_navmath/magnetic_field_gate.hpp>
#include <pednav_navmath/so3.hpp>

namespace pednav::attitude_ekf {

using navmath::Quat;
using navmath::Vec3;

struct AttitudeEkfConfig {
    double align_still_s;                   // still time that triggers the alignment, s
    double align_timeout_s;                 // align on the mean specific force after this long without one, s
    double still_gyro_max_radps;            // still: |w_m - bg| below this
    double still_accel_dev_mps2;            // still: ||a| - g| below this
    double gyro_noise_radps_per_sqrthz;     // Q of dphi
    double gyro_bias_walk_radps_per_sqrts;  // Q of dbg
    double accel_bias_walk_mps2_per_sqrts;  // Q of dba
    double init_tilt_sd_rad, init_heading_sd_rad, init_gyro_bias_sd_radps, init_accel_bias_sd_mps2;  // P0
    double gravity_update_s;                // window of one gravity update, s
    double gravity_sd_quiet_mps2;           // its sd when quiet (sd of |a| below quiet_accel_sd_mps2)
    double gravity_sd_moving_mps2;          // its sd otherwise (walking)
    double quiet_accel_sd_mps2;
    double still_bias_sd_radps;             // sd of a still window's mean rate as a gyro bias
    bool use_magnetometer;
    double declination_deg;                 // east positive: true heading = magnetic + declination
    double mag_heading_sd_rad;              // sd of one magnetometer heading
    double mag_deviation_sd_rad;            // P0 of the compass deviation's coefficients B, C; 0 = not estimated
    double mag_deviation_walk_rad_per_sqrts;  // their random walk (Q of dB, dC)
    double mag_update_s;                    // at most one magnetometer update per this long, s
    double mag_gate_chi2;                   // heading innovations beyond this (normalised, squared) are rejected
    int mag_max_rejections;                 // ... unless this many in a row: then the field resets the yaw
    navmath::MagneticFieldGateConfig mag_gate;
    double initial_heading_deg;             // yaw without magnetometer, app or GNSS, clockwise from north
    double gnss_course_min_speed_mps;       // a GNSS course sets the yaw at this speed or faster; 0 = never
    double max_dt_s;                        // longer gaps are integrated as this
};

// Fills a config from a params view (number(key), boolean(key)); the gate's
// under "mag_" (magnetic_field_gate_config).
template <class Params>
AttitudeEkfConfig attitude_ekf_config(Params& p) {
    AttitudeEkfConfig c;
    c.align_still_s = p.number("align_still_s");
    c.align_timeout_s = p.number("align_timeout_s");
    c.still_gyro_max_radps = p.number("still_gyro_max_radps");
    c.still_accel_dev_mps2 = p.number("still_accel_dev_mps2");
    c.gyro_noise_radps_per_sqrthz = p.number("gyro_noise_radps_per_sqrthz");
    c.gyro_bias_walk_radps_per_sqrts = p.number("gyro_bias_walk_radps_per_sqrts");
    c.accel_bias_walk_mps2_per_sqrts = p.number("accel_bias_walk_mps2_per_sqrts");
    c.init_tilt_sd_rad = p.number("init_tilt_sd_rad");
    c.init_heading_sd_rad = p.number("init_heading_sd_rad");
    c.init_gyro_bias_sd_radps = p.number("init_gyro_bias_sd_radps");
    c.init_accel_bias_sd_mps2 = p.number("init_accel_bias_sd_mps2");
    c.gravity_update_s = p.number("gravity_update_s");
    c.gravity_sd_quiet_mps2 = p.number("gravity_sd_quiet_mps2");
    c.gravity_sd_moving_mps2 = p.number("gravity_sd_moving_mps2");
    c.quiet_accel_sd_mps2 = p.number("quiet_accel_sd_mps2");
    c.still_bias_sd_radps = p.number("still_bias_sd_radps");
    c.use_magnetometer = p.boolean("use_magnetometer");
    c.declination_deg = p.number("declination_deg");
    c.mag_heading_sd_rad = p.number("mag_heading_sd_rad");
    c.mag_deviation_sd_rad = p.number("mag_deviation_sd_rad");
    c.mag_deviation_walk_rad_per_sqrts = p.number("mag_deviation_walk_rad_per_sqrts");
    c.mag_update_s = p.number("mag_update_s");
    c.mag_gate_chi2 = p.number("mag_gate_chi2");
    c.mag_max_rejections = static_cast<int>(p.integer("mag_max_rejections"));
    c.mag_gate = navmath::magnetic_field_gate_config(p, "mag_");
    c.initial_heading_deg = p.number("initial_heading_deg");
    c.gnss_course_min_speed_mps = p.number("gnss_course_min_speed_mps");
    c.max_dt_s = p.number("max_dt_s");
    return c;
}

// Where the yaw came from.
enum class YawSource { none, config, magnetometer, gnss_course, app };

class AttitudeEkf {
public:
    static constexpr int kStates = 11;  // dphi (3), dbg (3), dba (3), dB, dC
    using MatP = Eigen::Matrix<double, kStates, kStates>;
    using VecX = Eigen::Matrix<double, kStates, 1>;

    // Throws std::invalid_argument for a config out of range.
    explicit AttitudeEkf(const AttitudeEkfConfig& config);

    // One IMU sample; true once aligned (q() is then the attitude at t).
    bool on_imu(int64_t t_ns, const Vec3& accel_mps2, const Vec3& gyro_radps);
    void on_mag(int64_t t_ns, const Vec3& mag_ut);
    // A GNSS course over ground (clockwise from north) at a horizontal speed.
    void on_gnss_course(double course_rad, double speed_mps);
    // The app's attitude (its yaw wins over every other source from now on).
    void set_attitude(const Quat& q_enu_from_body);

    bool aligned() const { return aligned_; }
    const Quat& q() const { return q_; }
    const Vec3& gyro_bias() const { return bg_; }
    const Vec3& accel_bias() const { return ba_; }
    Eigen::Matrix3d attitude_cov() const { return P_.topLeftCorner<3, 3>(); }
    const MatP& covariance() const { return P_; }
    YawSource yaw_source() const { return yaw_source_; }
    // The compass deviation's coefficients (B, C), rad: a magnetometer
    // heading reads psi + B sin psi + C cos psi.
    const Eigen::Vector2d& mag_deviation_rad() const { return dev_; }
    // The magnetometer corrected the attitude since the last call.
    bool take_mag_used() {
        const bool u = mag_used_;
        mag_used_ = false;
        return u;
    }
    int64_t mag_updates() const { return mag_updates_; }

private:
    void align(const Vec3& f_mean, const Vec3& w_mean, bool bias_from_still);
    void propagate(const Vec3& w_radps, double dt);
    void window_sample(const Vec3& a, const Vec3& w, double dt);
    void end_window();
    void apply(const VecX& dx);
    void reset_covariance();
    void rotate_yaw(double delta_heading_rad);

    AttitudeEkfConfig c_;
    navmath::MagneticFieldGate gate_;
    bool aligned_ = false, has_t_ = false;
    int64_t t_ns_ = 0, t_start_ns_ = 0;
    Quat q_ = Quat::Identity();
    Vec3 bg_ = Vec3::Zero(), ba_ = Vec3::Zero();
    Eigen::Vector2d dev_ = Eigen::Vector2d::Zero();
    MatP P_ = MatP::Zero();
    double g_mps2_ = 9.80665;
    YawSource yaw_source_ = YawSource::none;
    bool mag_used_ = false;
    int64_t mag_updates_ = 0;
    int mag_rejections_ = 0;
    int64_t t_last_mag_update_ns_ = INT64_MIN / 2;

    // Before alignment: the current still run and the mean of everything.
    int64_t still_since_ns_ = 0;
    bool still_run_ = false;
    Vec3 still_f_sum_ = Vec3::Zero(), still_w_sum_ = Vec3::Zero();
    double still_n_ = 0;
    Vec3 all_f_sum_ = Vec3::Zero();
    double all_n_ = 0;
    Vec3 last_mag_ut_ = Vec3::Zero();
    int64_t t_last_mag_ns_ = INT64_MIN / 2;

    // The current update window.
    double win_s_ = 0, win_n_ = 0;
    Vec3 win_f_enu_ = Vec3::Zero(), win_w_ = Vec3::Zero();
    Eigen::Matrix3d win_r_ = Eigen::Matrix3d::Zero();
    double win_norm_sum_ = 0, win_norm_sq_ = 0;
    bool win_still_ = true;
};

}  // namespace pednav::attitude_ekf
