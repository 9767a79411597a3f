// SPDX-License-Identifier: Apache-2.0
// Step-length models besides the preset's (Weinberg's k (a_max - a_min)^(1/4)),
// evaluated on the ipol lower-back walks the way the preset's k is: the
// preset pipeline's steps of each annotated leg, their summed model lengths
// against the foot pipeline's leg (the mean of the trial's two foot files)
// times the waist's path-to-chord ratio over the leg, the constants fitted
// (pdr::fit_linear_step_model) on the other subjects' legs. The trials come
// from ipol_trials() with the preset.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <pednav_waist_eval/ipol_scores.hpp>

namespace pednav::waist_eval {

struct StepModelScores {
    std::string name;
    // Fitted on the other subjects (leave one subject out): waist / foot - 1
    // per leg, %, in the order of the trials (out, back).
    std::vector<double> loso_error_pct;
    // Fitted on the subject's own legs, the same legs.
    std::vector<double> own_error_pct;
    // Fitted on the subject's other trial (subjects with two), this trial's legs.
    std::vector<double> other_trial_error_pct;
    // The first constant fitted on each subject's own legs.
    std::map<std::string, double> constant_by_subject;
};

// The models, in this order: Weinberg; the same times the user's height;
// k r^(1/4) f^q (q fitted with k); a + b f; the inverted pendulum
// K 2 sqrt(2 l h - h^2) (pdr/inverted_pendulum.hpp) with l = 0.53 x the
// user's height; the same plus an offset; Weinberg plus an offset; k r^(1/b)
// with b fitted with k. A height the dataset lacks is
// taken as default_height_m.
std::vector<StepModelScores> score_step_models(const std::vector<IpolTrial>& trials, double default_height_m);

}  // namespace pednav::waist_eval
