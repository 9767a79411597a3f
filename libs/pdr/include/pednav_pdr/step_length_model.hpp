// SPDX-License-Identifier: Apache-2.0
// Step length from the acceleration of one step, and fitting its constants
// to walks of known length.
//
// The model (waist paper, eq. 3.1 as corrected in ERRATA.md; Weinberg's is
// b = 4, beta = 0):
//
//   L = k (a_max - a_min)^(1/b) + beta
//
// with a_max - a_min the range of the filtered acceleration within the step
// (m/s^2), k in m (m/s^2)^(-1/b), beta in m. The constants are per user.
#pragma once

#include <vector>

namespace pednav::pdr {

struct StepLengthModel {
    double k;       // m per (m/s^2)^(1/b)
    double b;       // root, > 0
    double beta_m;  // offset, m
};

// L for one step of acceleration range accel_range_mps2 (negative ranges read
// as 0); never below 0.
double step_length_m(const StepLengthModel& model, double accel_range_mps2);

// A model for a user never calibrated: beta = 0 and the given root, k such
// that a step of typical_range_mps2 is step_to_height times the user's height
// (0.415 is the usual ratio of step length to height at normal walking speed).
StepLengthModel step_length_model_for_height(double height_m, double step_to_height, double typical_range_mps2,
                                             double b);

// One walk of known length and the acceleration range of each of its steps.
struct CalibrationWalk {
    std::vector<double> accel_ranges_mps2;
    double distance_m;
};

struct StepLengthFit {
    StepLengthModel model;
    double rms_relative_error;  // over the walks: sqrt(mean(((sum L) - distance) / distance)^2)
    int walks;
};

// Least squares on the walks' relative distance errors, the root b fixed:
// k alone when fit_beta is false (beta stays beta_m), k and beta when it is
// true (needs walks with different step counts per metre; otherwise falls
// back to k alone). Throws std::invalid_argument for no walk, a walk without
// steps or a distance that is not positive.
StepLengthFit fit_step_length(const std::vector<CalibrationWalk>& walks, double b, bool fit_beta, double beta_m);

// The same with b chosen too: the b in [b_min, b_max] with the least error
// (golden-section search; k and beta refitted for each b).
StepLengthFit fit_step_length_and_root(const std::vector<CalibrationWalk>& walks, double b_min, double b_max,
                                       bool fit_beta, double beta_m);

// A step-length model linear in its constants, L = sum_j c_j g_j, with g_j
// what each step gives (r^(1/b), 1, the step frequency, the inverted
// pendulum's 2 sqrt(2 l h - h^2), ...). A walk of known length: the sums
// over its steps of each g_j.
struct LinearCalibrationWalk {
    std::vector<double> basis_sums;
    double distance_m;
};

// The constants c_j minimising the rms relative error of the walks' summed
// lengths, sum_j c_j G_wj against D_w (least squares on
// (sum_j c_j G_wj - D_w) / D_w, as fit_step_length). Throws
// std::invalid_argument for no walk, walks of different basis sizes, a
// distance that is not positive, or constants the walks do not determine.
std::vector<double> fit_linear_step_model(const std::vector<LinearCalibrationWalk>& walks);

}  // namespace pednav::pdr
