// SPDX-License-Identifier: Apache-2.0
// An estimated track to score: what the engine wrote (track CSV) or returned
// (pn_position_t), in metres in the ENU frame of the start point.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include <pednav/pn_types.h>

namespace pednav::eval {

struct TrackSample {
    double t_s = 0.0;
    double pos_m[3] = {0.0, 0.0, 0.0};
    double heading_deg = NAN;  // clockwise from north; NaN when unknown
    int floor = 0;
    bool has_floor = false;
};

struct Track {
    std::vector<TrackSample> samples;  // non-decreasing time
    std::vector<double> step_times_s;  // step events, when known
    bool has_steps = false;

    // Position at time t: linear interpolation, clamped to the track's ends.
    TrackSample at(double t_s) const;
    // Horizontal path length.
    double length_m() const;
};

// Reads the engine's track CSV (header t,x,y,z,heading_deg,floor,cov_xx,...;
// '#' comments; extra columns ignored). Throws std::runtime_error naming the
// file and line.
Track read_track_csv(const std::string& path);
// Step events from a CSV: the column t_end (pednav run --steps), else t, else
// the first column, in seconds ('#' comments skipped).
std::vector<double> read_step_times_csv(const std::string& path);

Track track_from_positions(const std::vector<pn_position_t>& positions);
// Step events from strides (end of each stride) or step records (the walking
// ones: a STATIC step record closes a pause).
std::vector<double> step_times_from_strides(const std::vector<pn_stride_t>& strides);
std::vector<double> step_times_from_steps(const std::vector<pn_step_t>& steps);

}  // namespace pednav::eval
