// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr_fusion/step_gnss_ekf.hpp"

#include <cmath>
#include <stdexcept>

#include <pednav_navmath/angles.hpp>
#include <pednav_navmath/kalman_update.hpp>

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
    // eq. (4.16) for E += L sin psi, N += L cos psi: F is the identity but
    // for the rows of E and N, so P <- F P F^T changes only their rows and
    // columns. With the rows r_E = F_E P and r_N = F_N P (of the P before):
    // P'(E, j) = r_E(j) for j not E, N; P'(E, E) = r_E F_E^T, P'(E, N) =
    // r_E F_N^T, P'(N, N) = r_N F_N^T.
    const double fe_psi = l * c, fe_l = s, fn_psi = -l * s, fn_l = c;
    double r_e[kStates], r_n[kStates];
    for (int j = 0; j < kStates; ++j) {
        r_e[j] = P_(E, j) + fe_psi * P_(PSI, j) + fe_l * P_(L, j);
        r_n[j] = P_(N, j) + fn_psi * P_(PSI, j) + fn_l * P_(L, j);
    }
    const double p_ee = r_e[E] + fe_psi * r_e[PSI] + fe_l * r_e[L];
    const double p_en = r_e[N] + fn_psi * r_e[PSI] + fn_l * r_e[L];
    const double p_nn = r_n[N] + fn_psi * r_n[PSI] + fn_l * r_n[L];
    for (int j = S; j < kStates; ++j) {
        P_(E, j) = P_(j, E) = r_e[j];
        P_(N, j) = P_(j, N) = r_n[j];
    }
    P_(E, E) = p_ee;
    P_(E, N) = P_(N, E) = p_en;
    P_(N, N) = p_nn;
    P_(E, E) += sq(c_.position_sd_m);
    P_(N, N) += sq(c_.position_sd_m);
    P_(S, S) += sq(c_.speed_sd_mps);
    P_(A, A) += sq(c_.altitude_sd_m);
    P_(PSI, PSI) += sq(c_.heading_sd_rad);
    P_(L, L) += sq(c_.step_length_sd_m);
    // eq. (4.22): S_INS = L f (the step length times the step frequency)
    // observes S; it is not a function of L in H, so the steps' own timing
    // does not move the length. The paper's L_INS (the model's length) is
    // the prediction's input above; applied again as an observation it
    // would pull what GNSS taught L back to the model during an outage.
    update_one(S, 1.0, x_(L) * frequency_hz - x_(S), sq(c_.model_speed_sd_mps));
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

void StepGnssEkf::update_one(int i, double h, double y, double r) {
    // One scalar observation y = h x_i + v (navmath/kalman_update.hpp:
    // the Joseph form, expanded for one row, O(N^2)).
    Vec dx = Vec::Zero();
    const int idx[1] = {i};
    const double val[1] = {h};
    navmath::kalman_scalar_update(P_, dx, idx, val, y, r);
    x_ += dx;
    x_(PSI) = navmath::wrap_pi(x_(PSI));
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
    // h = [E + S dt sin psi + bE, N + S dt cos psi + bN]: its two rows by
    // their nonzero entries (the column of bE, bN is absent with tau = 0:
    // those states stay 0 with no variance).
    const int idx_e[4] = {E, S, PSI, BE}, idx_n[4] = {N, S, PSI, BN};
    const double h_e[4] = {1.0, dt * s, v * dt * c, 1.0}, h_n[4] = {1.0, dt * c, -v * dt * s, 1.0};
    const double y_e = e_m - (x_(E) + v * dt * s + x_(BE)), y_n = n_m - (x_(N) + v * dt * c + x_(BN));
    const double r_var = sq(sd_w);
    // The gate: y^T S^-1 y with S = H P H^T + R (2 x 2).
    double s_ee = r_var, s_en = 0.0, s_nn = r_var;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
            s_ee += h_e[a] * P_(idx_e[a], idx_e[b]) * h_e[b];
            s_en += h_e[a] * P_(idx_e[a], idx_n[b]) * h_n[b];
            s_nn += h_n[a] * P_(idx_n[a], idx_n[b]) * h_n[b];
        }
    const double det = s_ee * s_nn - s_en * s_en;
    r.nis = det > 0 ? (s_nn * y_e * y_e - 2.0 * s_en * y_e * y_n + s_ee * y_n * y_n) / det : INFINITY;
    if (r.nis <= c_.gate_chi2) {
        // R is diagonal: the two components one after the other (the same
        // posterior as the joint update).
        Vec dx = Vec::Zero();
        navmath::kalman_scalar_update(P_, dx, idx_e, h_e, y_e, r_var);
        navmath::kalman_scalar_update(P_, dx, idx_n, h_n, y_n, r_var);
        x_ += dx;
        x_(PSI) = navmath::wrap_pi(x_(PSI));
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
    const Eigen::Vector2d y(y_e, y_n);
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
    const bool walking = !stopped_ && frequency_hz_ > 0;
    const int i = walking ? L : S;
    const double h = walking ? frequency_hz_ : 1.0;
    const double y = speed - h * x_(i), r_var = sq(sd);
    if (sq(y) > c_.gate_chi2 * (h * P_(i, i) * h + r_var)) return false;
    update_one(i, h, y, r_var);
    if (speed >= c_.gnss_course_min_speed_mps && c_.gnss_course_min_speed_mps > 0) {
        const double yc = navmath::wrap_pi(std::atan2(ve, vn) - x_(PSI)), rc = sq(sd / speed);
        if (sq(yc) <= c_.gate_chi2 * (P_(PSI, PSI) + rc)) update_one(PSI, 1.0, yc, rc);
    }
    return true;
}

void StepGnssEkf::altitude(double a_m, double sd_m) { update_one(A, 1.0, a_m - x_(A), sq(sd_m)); }

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
