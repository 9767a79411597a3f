// SPDX-License-Identifier: Apache-2.0
#include "gait_plan.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pednav::sim::detail {

namespace {

Eigen::Vector3d vec(const double v[3]) { return {v[0], v[1], v[2]}; }

}  // namespace

double level_stride_s(double stride_m, double stride_nominal_m, double stride_nominal_s) {
    const double s = std::clamp(stride_m / stride_nominal_m, kStrideRatioMin, kStrideRatioMax);
    return stride_nominal_s / s;
}

GaitPlan plan_gait(const Route& route) {
    if (route.waypoints.size() < 2) throw std::runtime_error("route: at least two waypoints are needed");
    GaitPlan plan;
    plan.step_nominal_m = route.step_length_m;
    const double stride_nominal_m = 2.0 * route.step_length_m;
    const double stride_nominal_s = stride_nominal_m / route.speed_mps;

    // First footprint: the start, facing the first segment that goes somewhere.
    double yaw = 0.0;
    for (size_t i = 1; i < route.waypoints.size(); ++i) {
        const Eigen::Vector3d d = vec(route.waypoints[i].enu_m) - vec(route.waypoints[i - 1].enu_m);
        if (d.head<2>().norm() > 1e-9) {
            yaw = std::atan2(d.y(), d.x());
            break;
        }
    }
    plan.prints.push_back({vec(route.waypoints[0].enu_m), yaw, 0, StrideKind::level});
    double t = route.start_still_s;
    plan.phases.push_back({0.0, t, false, 0, 0});

    for (size_t i = 1; i < route.waypoints.size(); ++i) {
        const Waypoint& wp = route.waypoints[i];
        const Eigen::Vector3d a = vec(route.waypoints[i - 1].enu_m), b = vec(wp.enu_m);
        const Eigen::Vector3d d = b - a;
        const double horizontal_m = d.head<2>().norm();
        if (horizontal_m > 1e-9) yaw = std::atan2(d.y(), d.x());
        // Fractions along the segment where the foot lands, and the stride time.
        std::vector<double> fractions;
        StrideKind kind = StrideKind::level;
        // Stairs: one foot per stair, so a stride spans two risers, at the stairs' own period; level:
        // equal strides near the nominal, at the walk ratio's cadence.
        const int risers =
            wp.stairs ? std::max(1, static_cast<int>(std::lround(std::fabs(d.z()) / route.stair_rise_m))) : 0;
        const int n = std::max(1, static_cast<int>(std::lround(horizontal_m / stride_nominal_m)));
        const double stride_s = wp.stairs
                                    ? 2.0 * route.stairs_step_period_s
                                    : level_stride_s(horizontal_m / n, stride_nominal_m, stride_nominal_s);
        if (wp.stairs) {
            kind = d.z() >= 0.0 ? StrideKind::stairs_up : StrideKind::stairs_down;
            for (int k = 2; k < risers + 2; k += 2) fractions.push_back(std::min(k, risers) / double(risers));
        } else {
            for (int k = 1; k <= n; ++k) fractions.push_back(k / double(n));
        }
        if (horizontal_m < 1e-9 && std::fabs(d.z()) < 1e-9) {
            // Same place: only the pause counts.
            plan.phases.back().t1_s += wp.still_s;
            t += wp.still_s;
            continue;
        }
        double f_prev = 0.0;
        for (size_t k = 0; k < fractions.size(); ++k) {
            const double f = fractions[k];
            const Eigen::Vector3d p = a + f * d;
            const int from = static_cast<int>(plan.prints.size()) - 1;
            plan.prints.push_back({p, yaw, static_cast<int>(i) - 1, kind});
            const int to = from + 1;
            // A stair stride over one riser instead of two takes half the time.
            const double this_stride_s =
                wp.stairs ? stride_s * 0.5 * std::lround((f - f_prev) * risers) : stride_s;
            f_prev = f;
            const double swing_s = (1.0 - route.stance_fraction) * this_stride_s;
            double stance_s = route.stance_fraction * this_stride_s;
            if (k + 1 == fractions.size()) stance_s += wp.still_s;
            plan.phases.push_back({t, t + swing_s, true, from, to});
            t += swing_s;
            plan.landing_s.push_back(t);
            plan.phases.push_back({t, t + stance_s, false, to, to});
            t += stance_s;
            plan.distance_m += (plan.prints[to].p_enu_m - plan.prints[from].p_enu_m).head<2>().norm();
        }
    }
    plan.phases.back().t1_s += route.end_still_s;
    plan.end_s = plan.phases.back().t1_s;
    return plan;
}

}  // namespace pednav::sim::detail
