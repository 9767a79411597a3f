// SPDX-License-Identifier: Apache-2.0
// One walk through a chest or handheld config, scored (docs/chest-pipeline.md,
// "Accuracy"): the report's metrics at the truth's checkpoints, and what the
// step pipelines add: walking steps, distance walked, loop closure, the share
// of attitudes the magnetometer corrected.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <pednav_engine/replay.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_eval/walks.hpp>

namespace pednav::chest_eval {

struct WalkScore {
    eval::Metrics metrics;          // horizontal error at the checkpoints, floors, ...
    size_t steps = 0;               // walking steps found (STATIC pause records left out)
    size_t true_steps = 0;          // 0 when unknown
    double distance_m = 0.0;        // the strides' lengths summed
    double true_distance_m = NAN;   // NaN when unknown
    double distance_error_pct = NAN;
    double closure_m = NAN;         // loops: horizontal distance from the first to the last position
    double mag_used_pct = 0.0;      // attitude records with PN_ATTITUDE_FLAG_MAG_USED
};

// A recording with landmarks (humolire), started at its known start point and
// heading, scored at every landmark. Throws std::runtime_error naming the
// walk when its files are missing or the run fails.
WalkScore score_recorded(const eval::RecordedWalk& walk, const std::string& config_json,
                         const std::vector<std::string>& plugin_dirs);

// A simulated walk, started at the truth's start point and heading, scored
// every 0.1 s (as pednav report does).
WalkScore score_sim(const eval::SimulatedWalk& walk, const std::string& config_json,
                    const std::vector<std::string>& plugin_dirs);

// A recording without truth (biba-chest-xsens): the run, attitudes kept.
ReplayResult run_recording(const std::string& path, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs);

// Walking steps (not STATIC) among the step records.
size_t walking_steps(const std::vector<pn_step_t>& steps);
// Share of attitude records with the magnetometer flag, percent.
double mag_used_pct(const std::vector<pn_attitude_t>& attitudes);

}  // namespace pednav::chest_eval
