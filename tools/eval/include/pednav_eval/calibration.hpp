// SPDX-License-Identifier: Apache-2.0
// Calibration of a step position filter from walks of known length (pednav
// calibrate): the constants are found by the filter's parameter names, so any
// position filter that declares them is calibrated the same way:
//   - step_vector_k (the chest step vector, K of eq. (1)): K times the ratio of
//     the true distance to the distance the run estimated, over every leg;
//   - step_model_k, step_model_b, step_model_beta_m (the step model, and the
//     waist filter): pdr::fit_step_length over the legs, from the acceleration
//     range of each walking step (k alone, or with beta, or with the root b).
// A leg is a stretch of a walk whose length is known: the whole walk
// (--distance-m), or the straight line between two consecutive timed
// landmarks.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_types.h>

namespace pednav::eval {

struct CalibrationLeg {
    double t_start_s, t_end_s;  // the strides (steps) that end within (t_start_s, t_end_s]
    double distance_m;          // > 0
};

// One run of the pipeline over a walk: its strides and step records, and the
// legs of it whose lengths are known.
struct CalibrationRun {
    std::string name;  // for messages: the input file
    std::vector<pn_stride_t> strides;
    std::vector<pn_step_t> steps;
    std::vector<CalibrationLeg> legs;
};

struct CalibrationOptions {
    bool fit_beta = false;  // step model: fit beta too (needs legs walked at different paces)
    bool fit_root = false;  // step model: fit b too, within [root_min, root_max]
    double root_min = 1.5, root_max = 6.0;
};

struct CalibrationResult {
    nlohmann::json params = nlohmann::json::object();  // the position filter's new values, by name
    std::vector<double> relative_errors_before, relative_errors_after;  // (estimated - true) / true, per leg
    std::string summary;                                                // one line per fitted value
};

// The legs between consecutive landmarks of a "t,x,y" file (s, m; a header
// line and # comments allowed): each leg's length is the straight line
// between them; or a humolire-phone walk folder (keypoints.json and
// references.txt). Throws std::runtime_error naming the file and line.
std::vector<CalibrationLeg> landmark_legs(const std::string& path);

// The whole walk as one leg.
CalibrationLeg whole_walk_leg(double distance_m);

// Fits the constants of `filter_params` (the position filter's params in the
// config, with every key its schema declares) to the runs. Throws
// std::runtime_error with a sentence saying why it cannot fit: neither
// parameter family present, a leg with no step, a fit out of range.
CalibrationResult calibrate_position_filter(const nlohmann::json& filter_params, const std::vector<CalibrationRun>& runs,
                                            const CalibrationOptions& options = {});

}  // namespace pednav::eval
