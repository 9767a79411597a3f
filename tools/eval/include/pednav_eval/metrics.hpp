// SPDX-License-Identifier: Apache-2.0
// Accuracy metrics of a track against a ground truth (definitions in
// docs/metrics.md), the alignment of the two frames, and their output as a
// table or JSON.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <pednav_eval/track.hpp>
#include <pednav_eval/truth.hpp>

namespace pednav::eval {

// ------------------------------------------------------------ statistics
struct AxisStats {  // of signed differences estimate - truth
    double min = NAN, max = NAN, mean = NAN, sd = NAN;
};
struct ErrorStats {  // of non-negative errors
    size_t n = 0;
    double mean = NAN, median = NAN, p75 = NAN, sd = NAN, max = NAN, rms = NAN;
};
// sd divides by n - ddof (see standard_deviation).
AxisStats axis_stats(const std::vector<double>& values, size_t ddof = 0);
ErrorStats error_stats(const std::vector<double>& values);
// How a percentile falls between two order statistics, at rank (n - 1) q / 100
// (numpy's methods of the same names): linear interpolates between them, higher
// takes the upper one (the median of an even count is then its upper middle value).
enum class PercentileMethod { linear, higher };
// Percentile q in [0, 100]; NaN for an empty input.
double percentile(std::vector<double> values, double q, PercentileMethod method = PercentileMethod::linear);
// Standard deviation dividing the squared deviations by n - ddof: 0 (the
// default) the population SD, as the papers' tables; 1 the sample SD. NaN when
// n <= ddof.
double standard_deviation(const std::vector<double>& values, size_t ddof = 0);
// a - b wrapped to (-180, 180].
double angle_diff_deg(double a_deg, double b_deg);
// IPIN competition score: 75th percentile of horizontal error + 15 m per floor wrong.
double ipin_score(const std::vector<double>& horizontal_m, const std::vector<int>& floor_diff);
// Loop closure as a percentage of the distance walked.
double loop_closure_pct(double closure_m, double distance_m);

// ------------------------------------------------------------- alignment
enum class Alignment {
    none,           // compare coordinates as they are
    start_point,    // translate the track so that it starts on the truth's start
    first_segment,  // start point, then rotate about it so the first segment's heading agrees
    fitted  // start point, then one 2-D rotation fitted on the first N checkpoints (Procrustes, rotation
            // only)
};
Alignment parse_alignment(const std::string& name);  // "none", "start", "first-segment", "fitted"; throws
const char* alignment_name(Alignment a);

// Rotation angle (rad, counter-clockwise) that best maps points a onto points b
// in least squares, both already relative to their start: the 2-D orthogonal
// Procrustes solution restricted to rotations.
double procrustes_rotation_rad(const std::vector<std::array<double, 2>>& a,
                               const std::vector<std::array<double, 2>>& b);

struct EvalOptions {
    Alignment alignment = Alignment::none;
    size_t fit_points = 5;         // fitted: checkpoints used (after the start), 0 = all
    double first_segment_m = 3.0;  // first_segment: the first checkpoint at least this far from the start
};

// The transform applied to the track: p' = R(rotation) (p - from) + to.
struct AlignmentResult {
    Alignment mode = Alignment::none;
    double rotation_deg = 0.0;  // counter-clockwise
    double from_m[2] = {0.0, 0.0};
    double to_m[2] = {0.0, 0.0};
    double z_offset_m = 0.0;  // added to the track's height
};
AlignmentResult align(const Track& track, const Truth& truth, const EvalOptions& options);
Track apply_alignment(const Track& track, const AlignmentResult& a);

// --------------------------------------------------------------- metrics
struct Metrics {
    std::string truth_kind;
    AlignmentResult alignment;
    size_t checkpoints = 0;
    AxisStats dx_m, dy_m;          // estimate - truth at the checkpoints
    ErrorStats horizontal_m;       // |(dx, dy)|
    double final_error_m = NAN;    // at the last checkpoint
    double ipin_score_m = NAN;     // when floors are known on both sides, else horizontal p75
    ErrorStats heading_error_deg;  // |angle difference| where the truth has a heading
    double height_error_mean_m = NAN, height_error_sd_m = NAN;  // estimate - truth where the truth has z
    double floor_correct_pct = NAN;
    double loop_closure_m = NAN, loop_closure_3d_m = NAN, loop_closure_pct = NAN;
    double distance_m = NAN;  // track's horizontal path length
    double truth_distance_m = NAN;
    int step_count = -1, truth_step_count = -1;
    std::vector<double> leg_lengths_m, leg_errors_pct;  // per known leg
    // Error against time (for plots): checkpoint times and horizontal errors.
    std::vector<double> t_s, error_m;
};

Metrics evaluate(const Track& track, const Truth& truth, const EvalOptions& options = {});

nlohmann::json to_json(const Metrics& m);
// A readable two-column table.
std::string format_table(const Metrics& m);

}  // namespace pednav::eval
