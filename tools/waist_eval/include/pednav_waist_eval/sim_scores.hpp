// SPDX-License-Identifier: Apache-2.0
// Simulated waist walks (pednav_sim) through the waist pipeline, scored
// against their exact truth: the error of every output, by its source, and
// the steps' motion modes against the route's stairs.
#pragma once

#include <string>
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

// The waist preset (configs/waist.json) read from the source tree.
std::string waist_preset(const std::string& source_dir);

}  // namespace pednav::waist_eval
