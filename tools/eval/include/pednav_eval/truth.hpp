// SPDX-License-Identifier: Apache-2.0
// Ground truth of a walk, whatever its kind: timed checkpoints (positions,
// optionally height, floor and heading), a closed loop, step events, legs of
// known length, and the walls of the map, all in one right-handed metric frame.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace pednav::eval {

enum class TruthKind {
    simulated,   // pednav sim truth.csv: dense, exact
    footprints,  // koroglu-foot-gcp: footprint position per stride, frame of the floor tiles
    landmarks,   // humolire-phone keypoints + reference times, map frame
    ipin_posi,   // IPIN competition POSI lines (WGS-84, floor)
    loop,        // a closed loop: the walk ends where it started
    step_events  // ipol-gait-waist-feet: footsteps and 10 m legs
};
const char* truth_kind_name(TruthKind kind);

struct TruthPoint {
    double t_s = 0.0;
    double x_m = 0.0, y_m = 0.0, z_m = NAN;  // z NaN when unknown
    int floor = 0;
    bool has_floor = false;
    double heading_deg = NAN;  // clockwise from north (of the truth frame's y axis); NaN when unknown
};

// A stretch of the walk between two times whose straight-line length is known.
struct Leg {
    double t0_s = 0.0, t1_s = 0.0;
    double length_m = 0.0;
};

struct WallLine {
    int floor = 0;
    std::vector<std::array<double, 2>> points_m;
};

struct Truth {
    TruthKind kind = TruthKind::simulated;
    std::string name;
    std::vector<TruthPoint> points;               // checkpoints in time order
    bool closed_loop = false;                     // the walk ends where it started
    double loop_start_s = NAN, loop_end_s = NAN;  // loop: NaN = the track's first / last sample
    double loop_length_m = NAN;  // known distance walked around the loop (NaN: use the track's)
    int step_count = -1;         // expected steps (-1 unknown); footprints: strides
    std::vector<double> step_times_s;
    std::vector<Leg> legs;
    double start_x_m = NAN, start_y_m = NAN;  // known start point (landmarks), NaN if unknown
    double start_heading_deg = NAN;           // known start heading, clockwise from the frame's y axis
    std::vector<WallLine> walls;              // map walls as polylines, same frame
    double distance_m = NAN;                  // distance walked when known (simulated)
};

}  // namespace pednav::eval
