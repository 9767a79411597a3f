// SPDX-License-Identifier: Apache-2.0
// The ipol lower-back (waist) walks through the waist pipeline, scored
// against the annotated footsteps and against the foot pipeline's estimate
// of the same 10 m legs from the same trial's two foot files.
#pragma once

#include <string>
#include <vector>

namespace pednav::waist_eval {

// Every trial in the folder (20 trials of 11 subjects); "s-t" is subject s, trial t.
const std::vector<std::string>& ipol_waist_trials();
std::string ipol_subject(const std::string& trial);

// What a step-length model can read from one detected step.
struct IpolStep {
    double accel_range_mps2 = 0;  // the step record's peak-to-peak
    double frequency_hz = 0;      // the step record's frequency
    double pelvis_rise_m = 0;     // pdr::pelvis_rise_m over the step's samples (pdr/inverted_pendulum.hpp)
};

struct IpolWaistRun {
    std::string trial;
    double height_m = 0;  // the subject's (the dataset's Height), NAN when unknown
    int steps = 0;      // detected steps within the walk: peaks within 0.3 s of the first and last heel strike
    int footsteps = 0;  // annotated footsteps of both feet within the trial
    // The dataset's legs (walk start to U-turn start, U-turn end to walk end,
    // foot_eval's annotated legs): the chord between the track's positions at
    // those times, linear between its per-step outputs.
    double leg_out_m = 0, leg_back_m = 0;
    std::vector<double> out_ranges_mps2, back_ranges_mps2;  // peak-to-peak of each leg's steps
    std::vector<IpolStep> out_steps, back_steps;             // the same steps
    double out_path_ratio = 1, back_path_ratio = 1;         // those steps' stride lengths over the chord
    double uturn_deg = 0;  // heading change between the two annotated legs (circular means)
};

// Runs <trial>_lb.txt through `config_json`; each leg's steps with the
// pelvis' rise from the recording's vertical acceleration
// (pdr::VerticalAcceleration with the config's gravity_time_constant_s).
IpolWaistRun run_ipol_waist(const std::string& data_dir, const std::string& trial, const std::string& config_json,
                            const std::vector<std::string>& plugin_dirs);

// The foot pipeline's annotated legs for the trial: the mean of its left and
// right foot files.
struct FootLegs {
    double out_m = 0, back_m = 0;
};
FootLegs ipol_foot_legs(const std::string& data_dir, const std::string& trial, const std::string& foot_config_json,
                        const std::vector<std::string>& plugin_dirs);

// One trial through the waist config and its two foot files through the foot config.
struct IpolTrial {
    std::string trial, subject;
    IpolWaistRun run;
    FootLegs foot;
};
std::vector<IpolTrial> ipol_trials(const std::string& data_dir, const std::string& waist_config_json,
                                   const std::string& foot_config_json, const std::vector<std::string>& plugin_dirs);

// The waist config with the step-length model's constants set.
std::string with_step_model(const std::string& config_json, double k, double b, double beta_m);

// Leave one subject out: for each subject, k of the step-length model (root
// b, beta 0) fitted (pdr::fit_step_length) on the other subjects' legs, the
// foot pipeline's leg lengths as their known distances; then that subject's
// walks through the pipeline with the fitted k.
struct LosoLeg {
    std::string trial, subject;
    bool out = true;
    double waist_m = 0, foot_m = 0;
    double k = 0;  // fitted without this subject
};
std::vector<LosoLeg> leave_one_subject_out(const std::string& data_dir, const std::string& waist_config_json,
                                           const std::string& foot_config_json,
                                           const std::vector<std::string>& plugin_dirs, double b);
// The same from trials already run (ipol_trials with the same waist config).
std::vector<LosoLeg> leave_one_subject_out(const std::vector<IpolTrial>& trials, const std::string& data_dir,
                                           const std::string& waist_config_json,
                                           const std::vector<std::string>& plugin_dirs, double b);

}  // namespace pednav::waist_eval
