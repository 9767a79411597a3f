// SPDX-License-Identifier: Apache-2.0
// The waist paper's fusion EKF (sec. 4.4), state
//   x = [E, N, S, A, psi, L, bE, bN]                  (eq. 4.14, and bE, bN)
// E, N, A in ENU metres, S the walking speed (m/s), psi the walking
// direction (azimuth, clockwise from north: one convention in the model and
// its Jacobian, ERRATA.md), L the step length (m); bE, bN the error of the
// GNSS fixes (m), correlated from one fix to the next (below).
//
// Per step k -> k+1 (eq. 4.15 as corrected), with the heading change of the
// attitude estimator over the step dpsi and the step-length model's value
// Lm (pednav_pdr):
//   psi' = psi + dpsi,   L' = L + (Lm_{k+1} - Lm_k),   pm = psi + dpsi/2,
//   E' = E + L' sin pm,   N' = N + L' cos pm,   S' = S,   A' = A
// (the step along the mean of its end headings: the paper's psi_k, the
// heading at the step's start, puts a turning step off by half its turn),
// so what GNSS teaches the filter about the walking direction (the offset
// between the sensor's heading and it) and about the step length (the
// model's error for this walker) stays in psi and L through an outage. The
// Jacobian (eq. 4.16 for this convention) has dE'/dpsi = L' cos pm,
// dE'/dL = sin pm, dN'/dpsi = -L' sin pm, dN'/dL = cos pm. Then the
// paper's INS pseudo-observation S_INS = L' f (eq. 4.22; f the step
// frequency, sd model_speed_sd_mps) as an observation of S alone (the step
// timing must not move L). Its L_INS (the model's length) is the
// prediction's input here; observed again it would pull what GNSS taught L
// back to the model during an outage. P0 of S, and
// its variance at the start of every walking bout, is (1 m/s)^2: the first
// steps set it, not L.
//
// GNSS (eq. 4.17-4.19) at a fix dt after the last step: position
// h = [E + S dt sin psi + bE, N + S dt cos psi + bN]. A fix's error (the
// atmosphere, multipath) changes over tens of seconds: taken as independent
// from fix to fix, a drift of it over a leg teaches the filter a wrong step
// length and walking direction. It is a first-order Gauss-Markov process
// per axis (gnss_error_time_s = tau; sigma_c^2 = sd^2 - sigma_w^2, the fix's
// sd per axis less its white part gnss_white_sd_m): from one fix to the
// next, dt apart, b <- phi b, P_bb <- phi^2 P_bb + (1 - phi^2) sigma_c^2,
// the covariances with b times phi, phi = exp(-dt / tau) (exact
// discretisation); the fix's own R is sigma_w^2. tau = 0: no b, R = sd^2.
// Velocity as speed L f (f the last
// step's frequency: a GNSS speed teaches the step length; S when standing)
// and, when fast enough, course psi. Every GNSS observation passes an innovation gate
// (normalised innovation squared below gate_chi2) or is rejected: a fix that
// jumps (multipath) does not move the track. gate_max_rejections rejected
// fixes in a row that agree with each other and with the steps between them
// (each innovation within recover_spread_m of the one before) mean the track
// is lost: it restarts at the fix.
// Barometric altitude observes A.
#pragma once

#include <cstdint>

#include <Eigen/Core>

namespace pednav::pdr_fusion {

struct StepGnssEkfConfig {
    double position_sd_m;         // process noise of E, N per step, m
    double speed_sd_mps;          // of S per step
    double altitude_sd_m;         // of A per step
    double heading_sd_rad;        // of psi per step (the attitude's heading drift)
    double step_length_sd_m;      // of L per step (the change of the model's error)
    double model_speed_sd_mps;    // sd of S_INS
    double init_position_sd_m;    // P0 of E, N
    double init_heading_sd_rad;   // P0 of psi
    double init_step_length_sd_m; // P0 of L
    double baro_altitude_sd_m;    // sd of a barometric altitude
    double gnss_min_sd_m;         // floor of a fix's sd per axis, m
    double gnss_velocity_sd_mps;  // sd of a GNSS velocity component
    double gnss_course_min_speed_mps;  // a course observes psi at this speed or faster
    double gnss_error_time_s;     // correlation time of the fixes' errors (Gauss-Markov states bE, bN); 0 = white
    double gnss_white_sd_m;       // the white part of a fix's sd per axis (the rest is correlated)
    double gate_chi2;             // innovation gate (2 degrees of freedom for a position)
    int gate_max_rejections;      // rejected, mutually consistent fixes in a row that restart the track
    double recover_spread_m;      // ... agreeing within this
};

template <class Params>
StepGnssEkfConfig step_gnss_ekf_config(Params& p) {
    StepGnssEkfConfig c;
    c.position_sd_m = p.number("position_sd_m");
    c.speed_sd_mps = p.number("speed_sd_mps");
    c.altitude_sd_m = p.number("altitude_sd_m");
    c.heading_sd_rad = p.number("heading_sd_rad");
    c.step_length_sd_m = p.number("step_length_sd_m");
    c.model_speed_sd_mps = p.number("model_speed_sd_mps");
    c.init_position_sd_m = p.number("init_position_sd_m");
    c.init_heading_sd_rad = p.number("init_heading_sd_rad");
    c.init_step_length_sd_m = p.number("init_step_length_sd_m");
    c.baro_altitude_sd_m = p.number("baro_altitude_sd_m");
    c.gnss_min_sd_m = p.number("gnss_min_sd_m");
    c.gnss_velocity_sd_mps = p.number("gnss_velocity_sd_mps");
    c.gnss_course_min_speed_mps = p.number("gnss_course_min_speed_mps");
    c.gnss_error_time_s = p.number("gnss_error_time_s");
    c.gnss_white_sd_m = p.number("gnss_white_sd_m");
    c.gate_chi2 = p.number("gate_chi2");
    c.gate_max_rejections = static_cast<int>(p.integer("gate_max_rejections"));
    c.recover_spread_m = p.number("recover_spread_m");
    return c;
}

// What became of a GNSS position.
struct FixResult {
    bool accepted = false;
    bool recovered = false;  // the track restarted at this fix
    double nis = 0;          // normalised innovation squared
};

class StepGnssEkf {
public:
    enum { E = 0, N = 1, S = 2, A = 3, PSI = 4, L = 5, BE = 6, BN = 7 };
    static constexpr int kStates = 8;
    using Vec = Eigen::Matrix<double, kStates, 1>;
    using Mat = Eigen::Matrix<double, kStates, kStates>;

    explicit StepGnssEkf(const StepGnssEkfConfig& config);

    // The first step (or the app's start): position, altitude, walking
    // direction, the model's step length.
    void start(double e_m, double n_m, double a_m, double psi_rad, double model_length_m);
    bool started() const { return started_; }

    // One step: the model's length, the heading change over it, its frequency (Hz, 0 = standing).
    void predict_step(double model_length_m, double dpsi_rad, double frequency_hz);
    // A turn on the spot (between steps): psi += dpsi, no displacement.
    void turn(double dpsi_rad);
    // Standing still: the speed is 0 (and the next bout's speed is unknown).
    void standing();

    // A fix at t_s (its time, for the error's correlation), sd_m per axis.
    FixResult gnss_position(double e_m, double n_m, double sd_m, double dt_since_step_s, double t_s);
    // GNSS velocity (ENU, m/s): speed and course; false when gated out.
    bool gnss_velocity(double ve_mps, double vn_mps, double sd_mps);
    void altitude(double a_m, double sd_m);

    // Moves the position (the app's start point) and optionally the heading.
    void set_position(double e_m, double n_m, double a_m);
    // Places the horizontal position at a fix known to sd_m per axis (its
    // covariance becomes the fix's: the start point's P0 is for a point the
    // app knows, not for a fix).
    void place_at_fix(double e_m, double n_m, double sd_m, double t_s);
    void set_heading(double psi_rad, double sd_rad);

    const Vec& x() const { return x_; }
    const Mat& P() const { return P_; }
    double model_length_m() const { return last_model_m_; }
    int consecutive_rejections() const { return rejections_; }

private:
    // One scalar observation y = h x_i + v, var r (y the innovation).
    void update_one(int i, double h, double y, double r);
    void forget_speed();
    // The fix's sd per axis split into its correlated and white parts.
    void split_sd(double sd_m, double& correlated_m, double& white_m) const;
    // bE, bN from the last fix to t_s (Gauss-Markov, exact discretisation).
    void decay_fix_error(double t_s, double correlated_sd_m);

    StepGnssEkfConfig c_;
    bool started_ = false, stopped_ = false;
    Vec x_ = Vec::Zero();
    Mat P_ = Mat::Zero();
    double t_fix_s_ = 0;
    bool has_fix_ = false;
    double last_model_m_ = 0;
    double frequency_hz_ = 0;  // of the last step
    int rejections_ = 0;
    Eigen::Vector2d rejected_last_ = Eigen::Vector2d::Zero();
    double rejected_spread_ = 0;
};

}  // namespace pednav::pdr_fusion
