// SPDX-License-Identifier: Apache-2.0
#include "pednav_attitude_ekf/attitude_ekf.hpp"

#include <cmath>
#include <stdexcept>

#include <pednav_navmath/alignment.hpp>
#include <pednav_navmath/angles.hpp>
#include <pednav_navmath/heading.hpp>
#include <pednav_navmath/kalman_update.hpp>

namespace pednav::attitude_ekf {

using Mat3 = Eigen::Matrix3d;
using MatP = AttitudeEkf::MatP;
using VecX = AttitudeEkf::VecX;

namespace {
constexpr int kN = AttitudeEkf::kStates;

const AttitudeEkfConfig& checked(const AttitudeEkfConfig& c) {
    if (!(c.align_still_s > 0) || !(c.align_timeout_s > 0))
        throw std::invalid_argument("align_still_s and align_timeout_s must be > 0");
    if (!(c.gravity_update_s > 0)) throw std::invalid_argument("gravity_update_s must be > 0");
    if (!(c.gravity_sd_quiet_mps2 > 0) || !(c.gravity_sd_moving_mps2 > 0) || !(c.still_bias_sd_radps > 0) ||
        !(c.mag_heading_sd_rad > 0))
        throw std::invalid_argument("measurement sds must be > 0");
    if (!(c.mag_deviation_sd_rad >= 0) || !(c.mag_deviation_walk_rad_per_sqrts >= 0))
        throw std::invalid_argument("mag_deviation_sd_rad and mag_deviation_walk_rad_per_sqrts must be >= 0");
    if (!(c.max_dt_s > 0)) throw std::invalid_argument("max_dt_s must be > 0");
    if (!(c.mag_gate_chi2 > 0) || c.mag_max_rejections < 1)
        throw std::invalid_argument("mag_gate_chi2 must be > 0 and mag_max_rejections >= 1");
    return c;
}
constexpr double kDeg = M_PI / 180.0;
}  // namespace

AttitudeEkf::AttitudeEkf(const AttitudeEkfConfig& config) : c_(checked(config)), gate_(config.mag_gate) {}

void AttitudeEkf::align(const Vec3& f_mean, const Vec3& w_mean, bool bias_from_still) {
    g_mps2_ = f_mean.norm();
    const Vec3 up_b = f_mean / g_mps2_;
    double yaw_rad = c_.initial_heading_deg * kDeg;
    yaw_source_ = YawSource::config;
    if (c_.use_magnetometer && t_ns_ - t_last_mag_ns_ < 500000000 && gate_.accept(t_last_mag_ns_, last_mag_ut_, up_b)) {
        yaw_rad = navmath::magnetic_heading(f_mean, last_mag_ut_) + c_.declination_deg * kDeg;
        yaw_source_ = YawSource::magnetometer;
        mag_used_ = true;
    }
    q_ = navmath::level_attitude(f_mean, yaw_rad);
    if (bias_from_still) bg_ = w_mean;
    reset_covariance();
    aligned_ = true;
}

void AttitudeEkf::reset_covariance() {
    P_.setZero();
    const double t = c_.init_tilt_sd_rad * c_.init_tilt_sd_rad;
    const double g = c_.init_gyro_bias_sd_radps * c_.init_gyro_bias_sd_radps;
    const double a = c_.init_accel_bias_sd_mps2 * c_.init_accel_bias_sd_mps2;
    const double d = c_.mag_deviation_sd_rad * c_.mag_deviation_sd_rad;
    P_.diagonal() << t, t, c_.init_heading_sd_rad * c_.init_heading_sd_rad, g, g, g, a, a, a, d, d;
}

bool AttitudeEkf::on_imu(int64_t t_ns, const Vec3& a, const Vec3& w) {
    double dt = has_t_ ? static_cast<double>(t_ns - t_ns_) * 1e-9 : 0.0;
    if (dt > c_.max_dt_s) dt = c_.max_dt_s;
    if (!has_t_) t_start_ns_ = t_ns;
    has_t_ = true;
    t_ns_ = t_ns;
    if (!aligned_) {
        all_f_sum_ += a;
        all_n_ += 1;
        const double g_est = (all_f_sum_ / all_n_).norm();
        const bool still = w.norm() < c_.still_gyro_max_radps && std::abs(a.norm() - g_est) < c_.still_accel_dev_mps2;
        if (!still) {
            still_run_ = false;
        } else {
            if (!still_run_) {
                still_run_ = true;
                still_since_ns_ = t_ns;
                still_f_sum_.setZero();
                still_w_sum_.setZero();
                still_n_ = 0;
            }
            still_f_sum_ += a;
            still_w_sum_ += w;
            still_n_ += 1;
            if (static_cast<double>(t_ns - still_since_ns_) * 1e-9 >= c_.align_still_s)
                align(still_f_sum_ / still_n_, still_w_sum_ / still_n_, true);
        }
        if (!aligned_ && static_cast<double>(t_ns - t_start_ns_) * 1e-9 >= c_.align_timeout_s)
            align(all_f_sum_ / all_n_, Vec3::Zero(), false);
        return aligned_;
    }
    propagate(w - bg_, dt);
    window_sample(a, w, dt);
    return true;
}

void AttitudeEkf::propagate(const Vec3& w, double dt) {
    q_ = navmath::quat_mul_unit(q_, navmath::quat_exp(w * dt));  // eq. (4.4)-(4.5)
    // P <- Phi P Phi^T + Q with Phi = [[I, -dt R, 0], [0, I, 0], [0, 0, I]]
    // (eq. 4.10 for errors defined as true minus estimated), by blocks.
    // P_aa gains B P_ag^T + P_ag B^T + B P_gg B^T = X + X^T with
    // X = (P_ag + B P_gg / 2) B^T (P_gg symmetric): exactly symmetric.
    const Mat3 B = -dt * q_.toRotationMatrix();
    const Mat3 Pgg = P_.block<3, 3>(3, 3), Pgb = P_.block<3, 3>(3, 6);
    const Mat3 BPgg = B * Pgg;
    const Mat3 X = (P_.block<3, 3>(0, 3) + 0.5 * BPgg) * B.transpose();
    P_.block<3, 3>(0, 0) += X + X.transpose();
    P_.block<3, 3>(0, 3) += BPgg;
    P_.block<3, 3>(0, 6) += B * Pgb;
    P_.block<3, 2>(0, 9) += B * P_.block<3, 2>(3, 9);  // the deviation's block of Phi is I
    P_.block<3, 3>(3, 0) = P_.block<3, 3>(0, 3).transpose();
    P_.block<3, 3>(6, 0) = P_.block<3, 3>(0, 6).transpose();
    P_.block<2, 3>(9, 0) = P_.block<3, 2>(0, 9).transpose();
    const double qa = c_.gyro_noise_radps_per_sqrthz * c_.gyro_noise_radps_per_sqrthz * dt;
    const double qg = c_.gyro_bias_walk_radps_per_sqrts * c_.gyro_bias_walk_radps_per_sqrts * dt;
    const double qb = c_.accel_bias_walk_mps2_per_sqrts * c_.accel_bias_walk_mps2_per_sqrts * dt;
    for (int i = 0; i < 3; ++i) {
        P_(i, i) += qa;
        P_(3 + i, 3 + i) += qg;
        P_(6 + i, 6 + i) += qb;
    }
    if (c_.mag_deviation_sd_rad > 0) {
        const double qd = c_.mag_deviation_walk_rad_per_sqrts * c_.mag_deviation_walk_rad_per_sqrts * dt;
        P_(9, 9) += qd;
        P_(10, 10) += qd;
    }
}

void AttitudeEkf::window_sample(const Vec3& a, const Vec3& w, double dt) {
    const Mat3 R = q_.toRotationMatrix();
    win_f_enu_ += R * (a - ba_);
    win_r_ += R;
    win_w_ += w;
    const double n = a.norm();
    win_norm_sum_ += n;
    win_norm_sq_ += n * n;
    win_n_ += 1;
    win_s_ += dt;
    if ((w - bg_).norm() >= c_.still_gyro_max_radps || std::abs(n - g_mps2_) >= c_.still_accel_dev_mps2)
        win_still_ = false;
    if (win_s_ >= c_.gravity_update_s) end_window();
}

void AttitudeEkf::end_window() {
    const double n = win_n_;
    const Vec3 f = win_f_enu_ / n;
    const Mat3 R = win_r_ / n;
    const double mean_norm = win_norm_sum_ / n;
    const double sd_norm = std::sqrt(std::max(0.0, win_norm_sq_ / n - mean_norm * mean_norm));
    const bool still = win_still_;
    const Vec3 w_mean = win_w_ / n;
    win_s_ = win_n_ = 0;
    win_f_enu_.setZero();
    win_w_.setZero();
    win_r_.setZero();
    win_norm_sum_ = win_norm_sq_ = 0;
    win_still_ = true;

    // Gravity: y = [f_E, f_N] = H dx, H = [[0, -g, 0, 0, R_E], [g, 0, 0, 0, R_N]];
    // R = sd^2 I, so one component after the other (the joint update's
    // posterior, navmath/kalman_update.hpp).
    const double sd = sd_norm < c_.quiet_accel_sd_mps2 ? c_.gravity_sd_quiet_mps2 : c_.gravity_sd_moving_mps2;
    VecX dx = VecX::Zero();
    const int idx_e[4] = {1, 6, 7, 8}, idx_n[4] = {0, 6, 7, 8};
    const double h_e[4] = {-g_mps2_, R(0, 0), R(0, 1), R(0, 2)}, h_n[4] = {g_mps2_, R(1, 0), R(1, 1), R(1, 2)};
    navmath::kalman_scalar_update(P_, dx, idx_e, h_e, f.x(), sd * sd);
    navmath::kalman_scalar_update(P_, dx, idx_n, h_n, f.y(), sd * sd);
    apply(dx);
    // Still: y = mean w_m - bg = dbg (H = [0, I, 0, 0], R = sd^2 I).
    if (still) {
        const Vec3 y = w_mean - bg_;
        const double r_var = c_.still_bias_sd_radps * c_.still_bias_sd_radps;
        dx.setZero();
        for (int j = 0; j < 3; ++j) {
            const int idx[1] = {3 + j};
            const double h[1] = {1.0};
            navmath::kalman_scalar_update(P_, dx, idx, h, y(j), r_var);
        }
        apply(dx);
    }
}

void AttitudeEkf::apply(const VecX& dx) {
    q_ = navmath::quat_mul_unit(navmath::quat_exp(dx.head<3>()), q_);
    bg_ += dx.segment<3>(3);
    ba_ += dx.segment<3>(6);
    dev_ += dx.tail<2>();
}

void AttitudeEkf::rotate_yaw(double delta_heading_rad) {
    // A heading increase is a clockwise turn: -delta about up.
    q_ = navmath::quat_mul_unit(navmath::quat_exp(Vec3(0, 0, -delta_heading_rad)), q_);
}

void AttitudeEkf::on_mag(int64_t t_ns, const Vec3& m) {
    last_mag_ut_ = m;
    t_last_mag_ns_ = t_ns;
    if (!aligned_ || !c_.use_magnetometer) return;
    const Vec3 up_b = q_.conjugate() * Vec3::UnitZ();
    if (!gate_.accept(t_ns, m, up_b)) return;
    if (t_ns - t_last_mag_update_ns_ < static_cast<int64_t>(c_.mag_update_s * 1e9)) return;
    t_last_mag_update_ns_ = t_ns;
    const double psi_mag = navmath::magnetic_heading(up_b, m) + c_.declination_deg * kDeg;
    const double psi = navmath::heading_of(q_), sin_psi = std::sin(psi), cos_psi = std::cos(psi);
    const double y = navmath::wrap_pi(psi_mag - psi - dev_(0) * sin_psi - dev_(1) * cos_psi);
    // H = [0, 0, -1, 0, ..., 0, sin psi, cos psi] (the deviation's entries 0
    // when it is not estimated: its states then have no variance).
    const bool deviation = c_.mag_deviation_sd_rad > 0;
    const int idx[3] = {2, 9, 10};
    const double h[3] = {-1.0, deviation ? sin_psi : 0.0, deviation ? cos_psi : 0.0};
    const double r_var = c_.mag_heading_sd_rad * c_.mag_heading_sd_rad;
    // A field the gate lets through may still be disturbed (a magnet can
    // keep the strength and dip): heading innovations beyond mag_gate_chi2
    // are rejected, unless mag_max_rejections in a row say the heading is
    // what is wrong.
    const double s2 = navmath::kalman_innovation_variance(P_, idx, h, r_var);
    const bool outlier = y * y > c_.mag_gate_chi2 * s2;
    if (outlier && yaw_source_ == YawSource::magnetometer && ++mag_rejections_ < c_.mag_max_rejections) return;
    mag_rejections_ = 0;
    if (outlier || (yaw_source_ != YawSource::magnetometer && yaw_source_ != YawSource::app)) {
        // The first accepted field (or a heading found wrong) gives the yaw outright.
        rotate_yaw(y);
        P_.row(2).setZero();
        P_.col(2).setZero();
        P_(2, 2) = c_.mag_heading_sd_rad * c_.mag_heading_sd_rad;
        yaw_source_ = YawSource::magnetometer;
    } else {
        VecX dx = VecX::Zero();
        navmath::kalman_scalar_update(P_, dx, idx, h, y, r_var);
        apply(dx);
    }
    mag_used_ = true;
    ++mag_updates_;
}

void AttitudeEkf::on_gnss_course(double course_rad, double speed_mps) {
    if (!aligned_ || !(c_.gnss_course_min_speed_mps > 0) || speed_mps < c_.gnss_course_min_speed_mps) return;
    if (yaw_source_ != YawSource::config && yaw_source_ != YawSource::none) return;
    rotate_yaw(navmath::wrap_pi(course_rad - navmath::heading_of(q_)));
    yaw_source_ = YawSource::gnss_course;
}

void AttitudeEkf::set_attitude(const Quat& q) {
    q_ = q.normalized();
    yaw_source_ = YawSource::app;
    if (!aligned_) {
        aligned_ = true;
        reset_covariance();
    }
}

}  // namespace pednav::attitude_ekf
