// SPDX-License-Identifier: Apache-2.0
// The timeline of a walk: where the instrumented foot lands (one footprint per
// stride, every waypoint is a footprint) and when it swings and stands.
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

struct GaitPlan {
    std::vector<Footprint> prints;
    std::vector<FootPhase> phases;  // contiguous, from t = 0 to end_s
    std::vector<double> landing_s;  // start of the stance after each swing
    double end_s = 0.0;
    double distance_m = 0.0;  // horizontal, footprint to footprint
};

GaitPlan plan_gait(const Route& route);

}  // namespace pednav::sim::detail
