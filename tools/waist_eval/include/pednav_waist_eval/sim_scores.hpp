// SPDX-License-Identifier: Apache-2.0
// Simulated waist walks (pednav_sim) through the waist pipeline, scored
// against their exact truth: the error of every output, by its source, and
// the steps' motion modes against the route's stairs.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <pednav_engine/replay.hpp>

namespace pednav::sim {
struct SimOutput;
struct Route;
}  // namespace pednav::sim

namespace pednav::waist_eval {

// Replays the simulated records (the caller may have changed out.gnss) with
// the engine's origin at the route's and imu_rate_hz the simulator's.
ReplayResult run_sim_waist(const sim::SimOutput& out, const sim::Route& route, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs);

// One output against the truth at its time.
struct OutputError {
    double t_s = 0;
    double err_h_m = 0;  // horizontal
    double err_e_m = 0, err_n_m = 0;
    int source = 0;      // PN_POSITION_SOURCE_*
    double walked_m = 0; // true horizontal distance walked up to t
    double true_e_m = 0, true_n_m = 0;  // the true position at t
    double var_e_m2 = 0, var_n_m2 = 0;  // the output's own variances (cov_enu_m2)
};
std::vector<OutputError> output_errors(const ReplayResult& r, const sim::SimOutput& out);

// Steps by motion mode against the truth's vertical speed over the step:
// climbing (above 0.15 m/s), descending, or level.
struct StairsScore {
    int up_steps = 0, up_labelled_up = 0;
    int down_steps = 0, down_labelled_down = 0;
    int level_steps = 0, level_labelled_stairs = 0;
};
StairsScore stairs_score(const ReplayResult& r, const sim::SimOutput& out);

// The longest gap between fixes: [last fix before it, first fix after it], s.
std::pair<double, double> longest_gnss_gap_s(const std::vector<pn_gnss_t>& fixes);

// Inside (t0, t1]: the largest growth of the error vector since the last
// output at or before t0, and the distance walked from there to t1. Its
// sources: the similarity (a scale and a rotation about the reference) that
// best maps the true displacements since the reference onto the estimated
// ones (least squares, as complex numbers: a = sum conj(z) w / sum |z|^2):
// the scale is what the step length was off by, the rotation what the
// walking direction was off by (azimuth, clockwise positive); and the
// largest growth left when the track is scaled back by the scale alone.
struct Drift {
    double max_m = 0, walked_m = 0;
    double scale_pct = 0;           // (|a| - 1) * 100
    double rotation_deg = 0;        // the azimuth error the fit's rotation means
    double max_without_scale_m = 0; // the drift of the track divided by |a|
};
Drift drift_in(const std::vector<OutputError>& errors, double t0_s, double t1_s);

// The true mean step length over the steps in (t0, t1]: half the mean chord
// between every other step (which cancels the trunk's sway), m; NAN with
// fewer than three steps.
double true_step_length_m(const sim::SimOutput& out, double t0_s, double t1_s);

// The learnt step length against the truth over the strides that end in
// (t0, t1]: their summed lengths over the true horizontal distance between
// each one's start and end, minus one, %; NAN without a stride.
double stride_length_error_pct(const ReplayResult& r, const sim::SimOutput& out, double t0_s, double t1_s);

// Mean horizontal error of the outputs of `source`, and how many there are.
double mean_error_of(const std::vector<OutputError>& errors, int source, int* count);
// The outputs of `source`: mean of err_e^2 / var_e and err_n^2 / var_n (1 when
// the output's covariance is the size of its error: a consistent filter).
double mean_nees_per_axis_of(const std::vector<OutputError>& errors, int source);
double mean_h_accuracy_m(const std::vector<pn_gnss_t>& fixes);
// Mean horizontal error of the fixes themselves against the truth at their
// time (in the route's ENU frame), of the fixes in [t0_s, t1_s].
double mean_fix_error_m(const sim::SimOutput& out, const sim::Route& route, double t0_s = -HUGE_VAL,
                        double t1_s = HUGE_VAL);

// Two laps of a 100 m x 60 m block outdoors (640 m, 8 turns): the long walk
// the 60 s GNSS outage is cut from (fixes of 300 to 360 s removed).
sim::Route block_laps_route();
constexpr double kBlockOutageStartS = 300.0, kBlockOutageEndS = 360.0;
void remove_fixes(sim::SimOutput& out, double t0_s, double t1_s);

// The waist preset (configs/waist.json) read from the source tree.
std::string waist_preset(const std::string& source_dir);

}  // namespace pednav::waist_eval
