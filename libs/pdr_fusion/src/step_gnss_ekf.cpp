// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr_fusion/step_gnss_ekf.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <pednav_navmath/angles.hpp>

namespace pednav::pdr_fusion {

namespace {
double sq(double x) { return x * x; }
}  // namespace

StepGnssEkf::StepGnssEkf(const StepGnssEkfConfig& c) : c_(c) {
    if (!(c.model_speed_sd_mps > 0) || !(c.baro_altitude_sd_m > 0) ||
        !(c.gnss_min_sd_m > 0) || !(c.gnss_velocity_sd_mps > 0) || !(c.gate_chi2 > 0))
        throw std::invalid_argument("step/GNSS EKF: observation sds and the gate must be > 0");
    if (!(c.gnss_error_time_s >= 0) || !(c.gnss_white_sd_m > 0))
        throw std::invalid_argument("step/GNSS EKF: gnss_error_time_s must be >= 0 and gnss_white_sd_m > 0");
    if (c.gate_max_rejections < 1) throw std::invalid_argument("step/GNSS EKF: gate_max_rejections must be >= 1");
}

void StepGnssEkf::start(double e_m, double n_m, double a_m, double psi_rad, double model_length_m) {
    x_ << e_m, n_m, 0.0, a_m, navmath::wrap_pi(psi_rad), model_length_m, 0.0, 0.0;
    P_.setZero();
    P_.diagonal() << sq(c_.init_position_sd_m), sq(c_.init_position_sd_m), 1.0, sq(c_.altitude_sd_m),
        sq(c_.init_heading_sd_rad), sq(c_.init_step_length_sd_m), 0.0, 0.0;
    has_fix_ = false;
    last_model_m_ = model_length_m;
    started_ = true;
    rejections_ = 0;
}

void StepGnssEkf::predict_step(double model_length_m, double dpsi_rad, double frequency_hz) {
    if (stopped_) {
        // A new bout: the speed of the last one says nothing about this one.
        forget_speed();
        stopped_ = false;
    }
    // eq. (4.15), heading as azimuth, with the step taken along the mean of
    // the headings at its two ends (the heading change over it is known; the
    // paper's psi_k, the heading at its start, puts each turning step off by
    // half its turn), and with the new length.
    const double psi_mid = x_(PSI) + 0.5 * dpsi_rad;
    x_(PSI) = navmath::wrap_pi(x_(PSI) + dpsi_rad);
    x_(L) += model_length_m - last_model_m_;
    last_model_m_ = model_length_m;
    frequency_hz_ = frequency_hz;
    const double s = std::sin(psi_mid), c = std::cos(psi_mid), l = x_(L);
    x_(E) += l * s;
    x_(N) += l * c;
    // eq. (4.16) for E += L sin psi, N += L cos psi.
    Mat F = Mat::Identity();
    F(E, PSI) = l * c;
    F(E, L) = s;
    F(N, PSI) = -l * s;
    F(N, L) = c;
    P_ = F * P_ * F.transpose();
    P_.diagonal().head<6>() += (Eigen::Matrix<double, 6, 1>() << sq(c_.position_sd_m), sq(c_.position_sd_m),
                                sq(c_.speed_sd_mps), sq(c_.altitude_sd_m), sq(c_.heading_sd_rad),
                                sq(c_.step_length_sd_m))
                                   .finished();
    // eq. (4.22): S_INS = L f (the step length times the step frequency)
    // observes S; it is not a function of L in H, so the steps' own timing
    // does not move the length. The paper's L_INS (the model's length) is
    // the prediction's input above; applied again as an observation it
    // would pull what GNSS taught L back to the model during an outage.
    Eigen::Matrix<double, 1, kStates> H = Eigen::Matrix<double, 1, kStates>::Zero();
    H(0, S) = 1.0;
    update<1>(Eigen::Matrix<double, 1, 1>(x_(L) * frequency_hz - x_(S)), H,
              Eigen::Matrix<double, 1, 1>(sq(c_.model_speed_sd_mps)));
}

void StepGnssEkf::turn(double dpsi_rad) { x_(PSI) = navmath::wrap_pi(x_(PSI) + dpsi_rad); }

void StepGnssEkf::standing() {
    forget_speed();
    x_(S) = 0.0;
    P_(S, S) = sq(c_.model_speed_sd_mps);
    stopped_ = true;
}

void StepGnssEkf::forget_speed() {
    P_.row(S).setZero();
    P_.col(S).setZero();
    P_(S, S) = 1.0;
}

template <int M>
double StepGnssEkf::nis(const Eigen::Matrix<double, M, 1>& y, const Eigen::Matrix<double, M, kStates>& H,
                        const Eigen::Matrix<double, M, M>& R, Eigen::Matrix<double, M, M>& S_out) const {
    S_out = H * P_ * H.transpose() + R;
    return y.dot(S_out.ldlt().solve(y));
}

template <int M>
void StepGnssEkf::update(const Eigen::Matrix<double, M, 1>& y, const Eigen::Matrix<double, M, kStates>& H,
                         const Eigen::Matrix<double, M, M>& R) {
    const Eigen::Matrix<double, M, M> S_ = H * P_ * H.transpose() + R;
    const Eigen::Matrix<double, kStates, M> K = P_ * H.transpose() * S_.inverse();
    x_ += K * y;
    x_(PSI) = navmath::wrap_pi(x_(PSI));
    const Mat IKH = Mat::Identity() - K * H;
    P_ = IKH * P_ * IKH.transpose() + K * R * K.transpose();  // Joseph form
}

void StepGnssEkf::split_sd(double sd_m, double& correlated_m, double& white_m) const {
    const double sd = std::max(sd_m, c_.gnss_min_sd_m);
    if (!(c_.gnss_error_time_s > 0)) {
        correlated_m = 0.0;
        white_m = sd;
        return;
    }
    white_m = std::min(sd, c_.gnss_white_sd_m);
    correlated_m = std::sqrt(std::max(0.0, sq(sd) - sq(white_m)));
}

void StepGnssEkf::decay_fix_error(double t_s, double correlated_sd_m) {
    if (!(c_.gnss_error_time_s > 0)) return;
    // b(t) = phi b(t0) + w, phi = exp(-(t - t0) / tau), var w = (1 - phi^2) sigma_c^2.
    const double phi = has_fix_ ? std::exp(-std::max(0.0, t_s - t_fix_s_) / c_.gnss_error_time_s) : 0.0;
    for (int i : {BE, BN}) {
        x_(i) *= phi;
        P_.row(i) *= phi;
        P_.col(i) *= phi;
    }
    P_(BE, BE) += (1.0 - phi * phi) * sq(correlated_sd_m);
    P_(BN, BN) += (1.0 - phi * phi) * sq(correlated_sd_m);
    t_fix_s_ = t_s;
    has_fix_ = true;
}

FixResult StepGnssEkf::gnss_position(double e_m, double n_m, double sd_m, double dt_since_step_s, double t_s) {
    FixResult r;
    const double dt = dt_since_step_s > 0 ? dt_since_step_s : 0.0;
    double sd_c = 0, sd_w = 0;
    split_sd(sd_m, sd_c, sd_w);
    const Vec x_before = x_;
    const Mat P_before = P_;
    const double t_fix_before = t_fix_s_;
    const bool had_fix = has_fix_;
    decay_fix_error(t_s, sd_c);
    const double s = std::sin(x_(PSI)), c = std::cos(x_(PSI)), v = x_(S);
    // h = [E + S dt sin psi + bE, N + S dt cos psi + bN]
    Eigen::Matrix<double, 2, kStates> H = Eigen::Matrix<double, 2, kStates>::Zero();
    H(0, E) = 1.0;
    H(0, S) = dt * s;
    H(0, PSI) = v * dt * c;
    H(1, N) = 1.0;
    H(1, S) = dt * c;
    H(1, PSI) = -v * dt * s;
    H(0, BE) = H(1, BN) = 1.0;
    const Eigen::Vector2d y(e_m - (x_(E) + v * dt * s + x_(BE)), n_m - (x_(N) + v * dt * c + x_(BN)));
    const Eigen::Matrix2d R = Eigen::Matrix2d::Identity() * sq(sd_w);
    Eigen::Matrix2d S_;
    r.nis = nis<2>(y, H, R, S_);
    if (r.nis <= c_.gate_chi2) {
        update<2>(y, H, R);
        rejections_ = 0;
        r.accepted = true;
        return r;
    }
    // A rejected fix says nothing about the error's correlation.
    x_ = x_before;
    P_ = P_before;
    t_fix_s_ = t_fix_before;
    has_fix_ = had_fix;
    // Rejected. Many in a row that agree with each other: the track is lost.
    // (Consecutive innovations that change little: the fixes agree with
    // each other and with the steps between them, the track is off.)
    if (rejections_ == 0) rejected_spread_ = 0;
    else rejected_spread_ = std::max(rejected_spread_, (y - rejected_last_).norm());
    rejected_last_ = y;
    ++rejections_;
    if (rejections_ >= c_.gate_max_rejections && rejected_spread_ <= c_.recover_spread_m) {
        place_at_fix(e_m - v * dt * s, n_m - v * dt * c, sd_m, t_s);
        rejections_ = 0;
        r.recovered = true;
        r.accepted = true;
    }
    return r;
}

bool StepGnssEkf::gnss_velocity(double ve, double vn, double sd_mps) {
    const double sd = std::max(sd_mps, c_.gnss_velocity_sd_mps);
    const double speed = std::hypot(ve, vn);
    // Walking: the speed is the step length times the step frequency, so a
    // GNSS speed observes L (the model's error for this walker); standing,
    // it observes S.
    Eigen::Matrix<double, 1, kStates> H = Eigen::Matrix<double, 1, kStates>::Zero();
    double predicted = x_(S);
    if (!stopped_ && frequency_hz_ > 0) {
        H(0, L) = frequency_hz_;
        predicted = x_(L) * frequency_hz_;
    } else {
        H(0, S) = 1.0;
    }
    const Eigen::Matrix<double, 1, 1> y(speed - predicted), R(sq(sd));
    Eigen::Matrix<double, 1, 1> S_;
    if (nis<1>(y, H, R, S_) > c_.gate_chi2) return false;
    update<1>(y, H, R);
    if (speed >= c_.gnss_course_min_speed_mps && c_.gnss_course_min_speed_mps > 0) {
        H.setZero();
        H(0, PSI) = 1.0;
        const Eigen::Matrix<double, 1, 1> yc(navmath::wrap_pi(std::atan2(ve, vn) - x_(PSI))), Rc(sq(sd / speed));
        if (nis<1>(yc, H, Rc, S_) <= c_.gate_chi2) update<1>(yc, H, Rc);
    }
    return true;
}

void StepGnssEkf::altitude(double a_m, double sd_m) {
    Eigen::Matrix<double, 1, kStates> H = Eigen::Matrix<double, 1, kStates>::Zero();
    H(0, A) = 1.0;
    update<1>(Eigen::Matrix<double, 1, 1>(a_m - x_(A)), H, Eigen::Matrix<double, 1, 1>(sq(sd_m)));
}

void StepGnssEkf::set_position(double e_m, double n_m, double a_m) {
    x_(E) = e_m;
    x_(N) = n_m;
    x_(A) = a_m;
}

void StepGnssEkf::place_at_fix(double e_m, double n_m, double sd_m, double t_s) {
    double sd_c = 0, sd_w = 0;
    split_sd(sd_m, sd_c, sd_w);
    has_fix_ = false;
    x_(BE) = x_(BN) = 0.0;
    for (int i : {E, N, BE, BN}) {
        P_.row(i).setZero();
        P_.col(i).setZero();
    }
    decay_fix_error(t_s, sd_c);
    // The track at the fix: E = e - bE - w, so var E = sigma_c^2 + sigma_w^2, cov(E, bE) = -sigma_c^2.
    x_(E) = e_m;
    x_(N) = n_m;
    P_(E, E) = P_(N, N) = sq(sd_c) + sq(sd_w);
    P_(E, BE) = P_(BE, E) = P_(N, BN) = P_(BN, N) = -sq(sd_c);
}

void StepGnssEkf::set_heading(double psi_rad, double sd_rad) {
    x_(PSI) = navmath::wrap_pi(psi_rad);
    P_.row(PSI).setZero();
    P_.col(PSI).setZero();
    P_(PSI, PSI) = sq(sd_rad);
}

}  // namespace pednav::pdr_fusion
