// SPDX-License-Identifier: Apache-2.0
// The timeline of a walk: where the instrumented foot lands (one footprint per
// stride, every waypoint is a footprint) and when it swings and stands.
//
// A level segment gets round(length / nominal stride) equal strides. Their
// timing keeps the walk ratio (step length over cadence) of the nominal gait,
// as real walkers do: a stride s times the nominal length takes the nominal
// stride time divided by s, so the speed is Route::speed_mps times s^2
// (speed_mps is the speed at the nominal step). s is taken within
// [kStrideRatioMin, kStrideRatioMax] for the timing, so that a very short or
// very long quantised stride keeps a plausible cadence. A flight of stairs
// keeps its own period (stairs_step_period_s per stair).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include <pednav_sim/route.hpp>

namespace pednav::sim::detail {

enum class StrideKind { level, stairs_up, stairs_down };

struct Footprint {
    Eigen::Vector3d p_enu_m;
    double yaw_enu_rad = 0.0;  // foot direction while standing here (direction of the stride that led here)
    int segment = 0;           // route segment of the stride that led here (0 for the start)
    StrideKind kind = StrideKind::level;  // the stride that led here
};

// Stance at footprint `to` (from == to), or the swing from `from` to `to`.
struct FootPhase {
    double t0_s = 0.0, t1_s = 0.0;
    bool swing = false;
    int from = 0, to = 0;
};

// The stride ratio s beyond which the cadence stops following the stride
// length: a stride takes at most twice and at least 0.6 times the nominal
// stride time.
constexpr double kStrideRatioMin = 0.5;
constexpr double kStrideRatioMax = 1.0 / 0.6;

// Time of one level stride of length stride_m: the nominal stride time
// divided by s = stride_m / stride_nominal_m (s clamped as above).
double level_stride_s(double stride_m, double stride_nominal_m, double stride_nominal_s);

struct GaitPlan {
    std::vector<Footprint> prints;
    std::vector<FootPhase> phases;  // contiguous, from t = 0 to end_s
    std::vector<double> landing_s;  // start of the stance after each swing
    double end_s = 0.0;
    double distance_m = 0.0;      // horizontal, footprint to footprint
    double step_nominal_m = 0.0;  // the route's step_length_m (half the nominal stride)
};

GaitPlan plan_gait(const Route& route);

}  // namespace pednav::sim::detail
