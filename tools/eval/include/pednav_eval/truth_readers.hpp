// SPDX-License-Identifier: Apache-2.0
// Readers for every kind of ground truth the project has (see docs/metrics.md
// and each shared recording's SOURCE.md). Each throws std::runtime_error naming
// the file (and line) on malformed input.
#pragma once

#include <string>
#include <vector>

#include <pednav_eval/truth.hpp>

namespace pednav::sim {
struct SimOutput;
struct Route;
}  // namespace pednav::sim

namespace pednav::eval {

// The truth of a simulated walk from every sample of it (`rows`, in time order:
// position, height, floor, walking heading) and its step event times:
// checkpoints every `period_s` from the first row, and the last row; the
// distance along the rows; a closed loop when the last row is within 5 cm of
// the first, horizontally and in height. No walls. Throws std::runtime_error
// when `rows` is empty.
Truth sim_truth(const std::vector<TruthPoint>& rows, std::vector<double> step_times_s, double period_s = 0.1);

// The same from a simulated walk in memory (pednav report): the truth that
// read_sim_truth() reads back from write_outputs(out, route), walls included.
Truth sim_truth(const sim::SimOutput& out, const sim::Route& route, double period_s = 0.1);

// pednav sim truth.csv through sim_truth (a step event on each row with step
// 1), with the walls of route.json when it sits next to truth.csv.
Truth read_sim_truth(const std::string& truth_csv, double period_s = 0.1);

// koroglu-foot-gcp *_gcp.csv: one footprint per stride at the end of its
// stance (timestamp_s); stride 0 is the start. step_count = number of strides.
Truth read_koroglu_gcp(const std::string& gcp_csv);

// humolire-phone walk folder (keypoints.json + references.txt): landmark k at
// reference time k, the known start point and heading, and the walls of
// ../maps/map_data.json when present, all in the dataset's metres: x right,
// y up from the map image's bottom edge (the walls' pixels are turned so,
// as pednav map convert --from humolire does).
Truth read_humolire(const std::string& walk_dir);

// IPIN competition logfile or ground-truth file: every "POSI;t;counter;lat;lon;floor;building"
// line, converted to metres east/north of the first POSI point.
Truth read_ipin_posi(const std::string& path);

// A closed loop: the walk ends where it started; the distance walked is known
// when length_m is finite, otherwise the track's own length is used.
Truth make_loop_truth(double length_m = NAN);

// ipol-gait-waist-feet <subject>-<trial>.json: the footsteps within the trial
// (times at each step's heel strike), and the two 10 m legs (start of trial to
// start of U-turn, end of U-turn to end of trial). feet: "both" (a waist
// sensor's steps: left + right), "left" or "right" (a foot sensor's strides).
// whole_recording: every annotated footstep, also those before and after the trial.
Truth read_ipol_steps(const std::string& json_path, double rate_hz = 100.0, double leg_length_m = 10.0,
                      const std::string& feet = "both", bool whole_recording = false);

// The subject's height in the same file ("Height", cm), m; NAN when the file
// has none (subject 10's is NaN).
double read_ipol_height_m(const std::string& json_path);

// By kind name: "sim", "koroglu", "humolire", "ipin", "loop" (or "loop:LENGTH_M"),
// "ipol"; "auto" guesses from the path.
Truth read_truth(const std::string& path, const std::string& kind = "auto");

}  // namespace pednav::eval
