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
    if (c.gate_max_rejections < 1) throw std::invalid_argument("step/GNSS EKF: gate_max_rejections must be >= 1");
}

void StepGnssEkf::start(double e_m, double n_m, double a_m, double psi_rad, double model_length_m) {
    x_ << e_m, n_m, 0.0, a_m, navmath::wrap_pi(psi_rad), model_length_m;
    P_.setZero();
    P_.diagonal() << sq(c_.init_position_sd_m), sq(c_.init_position_sd_m), 1.0, sq(c_.altitude_sd_m),
        sq(c_.init_heading_sd_rad), sq(c_.init_step_length_sd_m);
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
    Mat6 F = Mat6::Identity();
    F(E, PSI) = l * c;
    F(E, L) = s;
    F(N, PSI) = -l * s;
    F(N, L) = c;
    P_ = F * P_ * F.transpose();
    P_.diagonal() += (Vec6() << sq(c_.position_sd_m), sq(c_.position_sd_m), sq(c_.speed_sd_mps), sq(c_.altitude_sd_m),
                      sq(c_.heading_sd_rad), sq(c_.step_length_sd_m))
                         .finished();
    // eq. (4.22): S_INS = L f (the step length times the step frequency)
    // observes S; it is not a function of L in H, so the steps' own timing
    // does not move the length. The paper's L_INS (the model's length) is
    // the prediction's input above; applied again as an observation it
    // would pull what GNSS taught L back to the model during an outage.
    Eigen::Matrix<double, 1, 6> H = Eigen::Matrix<double, 1, 6>::Zero();
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
double StepGnssEkf::nis(const Eigen::Matrix<double, M, 1>& y, const Eigen::Matrix<double, M, 6>& H,
                        const Eigen::Matrix<double, M, M>& R, Eigen::Matrix<double, M, M>& S_out) const {
    S_out = H * P_ * H.transpose() + R;
    return y.dot(S_out.ldlt().solve(y));
}

template <int M>
void StepGnssEkf::update(const Eigen::Matrix<double, M, 1>& y, const Eigen::Matrix<double, M, 6>& H,
                         const Eigen::Matrix<double, M, M>& R) {
    const Eigen::Matrix<double, M, M> S_ = H * P_ * H.transpose() + R;
    const Eigen::Matrix<double, 6, M> K = P_ * H.transpose() * S_.inverse();
    x_ += K * y;
    x_(PSI) = navmath::wrap_pi(x_(PSI));
    const Mat6 IKH = Mat6::Identity() - K * H;
    P_ = IKH * P_ * IKH.transpose() + K * R * K.transpose();  // Joseph form
}

FixResult StepGnssEkf::gnss_position(double e_m, double n_m, double sd_m, double dt_since_step_s) {
    FixResult r;
    const double dt = dt_since_step_s > 0 ? dt_since_step_s : 0.0;
    const double s = std::sin(x_(PSI)), c = std::cos(x_(PSI)), v = x_(S);
    Eigen::Matrix<double, 2, 6> H = Eigen::Matrix<double, 2, 6>::Zero();
    H(0, E) = 1.0;
    H(0, S) = dt * s;
    H(0, PSI) = v * dt * c;
    H(1, N) = 1.0;
    H(1, S) = dt * c;
    H(1, PSI) = -v * dt * s;
    const Eigen::Vector2d y(e_m - (x_(E) + v * dt * s), n_m - (x_(N) + v * dt * c));
    const double sd = std::max(sd_m, c_.gnss_min_sd_m);
    const Eigen::Matrix2d R = Eigen::Matrix2d::Identity() * sq(sd);
    Eigen::Matrix2d S_;
    r.nis = nis<2>(y, H, R, S_);
    if (r.nis <= c_.gate_chi2) {
        update<2>(y, H, R);
        rejections_ = 0;
        r.accepted = true;
        return r;
    }
    // Rejected. Many in a row that agree with each other: the track is lost.
    // (Consecutive innovations that change little: the fixes agree with
    // each other and with the steps between them, the track is off.)
    if (rejections_ == 0) rejected_spread_ = 0;
    else rejected_spread_ = std::max(rejected_spread_, (y - rejected_last_).norm());
    rejected_last_ = y;
    ++rejections_;
    if (rejections_ >= c_.gate_max_rejections && rejected_spread_ <= c_.recover_spread_m) {
        x_(E) += y.x();
        x_(N) += y.y();
        P_.row(E).setZero();
        P_.col(E).setZero();
        P_.row(N).setZero();
        P_.col(N).setZero();
        P_(E, E) = P_(N, N) = sq(sd);
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
    Eigen::Matrix<double, 1, 6> H = Eigen::Matrix<double, 1, 6>::Zero();
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
    Eigen::Matrix<double, 1, 6> H = Eigen::Matrix<double, 1, 6>::Zero();
    H(0, A) = 1.0;
    update<1>(Eigen::Matrix<double, 1, 1>(a_m - x_(A)), H, Eigen::Matrix<double, 1, 1>(sq(sd_m)));
}

void StepGnssEkf::set_position(double e_m, double n_m, double a_m) {
    x_(E) = e_m;
    x_(N) = n_m;
    x_(A) = a_m;
}

void StepGnssEkf::place_at_fix(double e_m, double n_m, double sd_m) {
    x_(E) = e_m;
    x_(N) = n_m;
    for (int i : {E, N}) {
        P_.row(i).setZero();
        P_.col(i).setZero();
    }
    P_(E, E) = P_(N, N) = sq(std::max(sd_m, c_.gnss_min_sd_m));
}

void StepGnssEkf::set_heading(double psi_rad, double sd_rad) {
    x_(PSI) = navmath::wrap_pi(psi_rad);
    P_.row(PSI).setZero();
    P_.col(PSI).setZero();
    P_(PSI, PSI) = sq(sd_rad);
}

}  // namespace pednav::pdr_fusion
