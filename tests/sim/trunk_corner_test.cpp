// SPDX-License-Identifier: Apache-2.0
// The trunk rounds a corner (docs/simulator.md, "Kinematics"): its path is the
// landings smoothed, (p[k-1] + 2 p[k] + p[k+1]) / 4, and its yaw the path's
// own direction, so at a 90 deg corner each step's chord and its mean yaw over
// the step agree; straight, evenly stepped legs stay on the landings, and the
// heights are the landings' own (on stairs too).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>

#include <pednav_sim/route.hpp>

#include "body_kinematics.hpp"
#include "gait_plan.hpp"

using namespace pednav::sim;
using namespace pednav::sim::detail;

namespace {

constexpr double kDeg = 180.0 / M_PI;
constexpr double kStepM = 0.7;  // the route's step_length_m

// 10 nominal strides east, a 90 deg left turn on the footprint at (14, 0), 10 strides north.
Route corner_route() {
    Route r;
    r.name = "corner";
    r.start_still_s = 2.0;
    r.end_still_s = 2.0;
    Waypoint w;
    r.waypoints.push_back(w);
    w.enu_m[0] = 20 * kStepM;
    r.waypoints.push_back(w);
    w.enu_m[1] = 20 * kStepM;
    r.waypoints.push_back(w);
    return r;
}

// Where the feet land, one per step (either foot), after the start: the other foot halfway, then
// the instrumented foot on its footprint, as the trunk's knots are laid (one walking bout).
std::vector<Eigen::Vector3d> landings(const GaitPlan& plan) {
    std::vector<Eigen::Vector3d> p;
    for (const FootPhase& ph : plan.phases)
        if (ph.swing) {
            const Eigen::Vector3d a = plan.prints[ph.from].p_enu_m, b = plan.prints[ph.to].p_enu_m;
            p.push_back(0.5 * (a + b));
            p.push_back(b);
        }
    return p;
}

// The trunk with no bounce and no sway: its path alone.
BodyShape path_only(BodyShape s) {
    s.bounce_m = s.sway_m = 0.0;
    return s;
}

}  // namespace

TEST_CASE("trunk at a 90 deg corner: each step's chord and its mean yaw agree, straight legs unchanged") {
    const GaitPlan plan = plan_gait(corner_route());
    BodyKinematics body(plan, BodyShape::chest());
    const std::vector<double> steps = body.step_times_s();  // every landing of either foot
    const std::vector<Eigen::Vector3d> feet = landings(plan);
    REQUIRE(steps.size() == 40);
    REQUIRE(feet.size() == steps.size());
    const size_t corner = 19;  // the landing on the corner's footprint
    REQUIRE((feet[corner] - Eigen::Vector3d(20 * kStepM, 0.0, 0.0)).norm() < 1e-9);

    // Over each step between two landings: the chord (the trunk's displacement), its mean yaw over
    // the step (the chest step model's heading) and the mean of its yaws at both ends (the waist
    // fusion's), at 1 kHz. The sway is zero at each landing, so the chord is the path's.
    double worst_mean_deg = 0.0, worst_ends_deg = 0.0, worst_straight_deg = 0.0;
    for (size_t k = 1; k < steps.size(); ++k) {
        const double t0 = steps[k - 1], t1 = steps[k];
        const int n = static_cast<int>(std::lround((t1 - t0) * 1000.0));
        double yaw_sum = 0.0, yaw0 = 0.0, yaw1 = 0.0;
        Eigen::Vector3d p0, p1;
        for (int i = 0; i <= n; ++i) {
            const KinState s = body.at(t0 + (t1 - t0) * i / n);
            if (i == 0) p0 = s.p_enu_m, yaw0 = s.yaw_enu_rad;
            if (i == n) p1 = s.p_enu_m, yaw1 = s.yaw_enu_rad;
            if (i > 0) yaw_sum += s.yaw_enu_rad;  // the right end of each millisecond
        }
        const Eigen::Vector3d d = p1 - p0;
        const double chord_deg = std::atan2(d.y(), d.x()) * kDeg, mean_deg = yaw_sum / n * kDeg,
                     ends_deg = 0.5 * (yaw0 + yaw1) * kDeg;
        CAPTURE(k);
        if (k + 3 >= corner && k <= corner + 4)
            std::printf(
                "trunk corner step %2zu: chord %6.2f deg, mean yaw %6.2f deg (%+5.2f), mean of its end yaws "
                "%6.2f deg (%+5.2f)\n",
                k, chord_deg, mean_deg, mean_deg - chord_deg, ends_deg, ends_deg - chord_deg);
        worst_mean_deg = std::max(worst_mean_deg, std::fabs(mean_deg - chord_deg));
        worst_ends_deg = std::max(worst_ends_deg, std::fabs(ends_deg - chord_deg));
        // On the legs, four steps or more from the corner: the leg's direction.
        if (k + 4 <= corner || k >= corner + 5)
            worst_straight_deg =
                std::max(worst_straight_deg, std::fabs(mean_deg - (k < corner ? 0.0 : 90.0)));
    }
    std::printf(
        "trunk corner: worst |mean yaw - chord| %.2f deg, |mean of end yaws - chord| %.2f deg; on the legs "
        "|mean yaw - leg| %.3f deg\n",
        worst_mean_deg, worst_ends_deg, worst_straight_deg);
    // Passing exactly over the corner's footprint, the trunk turned 0 -> 45 deg over the step into it while
    // its chord pointed along the first leg: 19.5 deg off (22.5 deg for the mean of the end yaws).
    CHECK(worst_mean_deg < 2.0);  // 1.3 deg
    // The mean of the end yaws is the path's: its curvature peaks at the corner's knot, so it turns more
    // towards the end of the step into it than a circle would (for which the two agree).
    CHECK(worst_ends_deg < 7.0);  // 6.1 deg
    CHECK(worst_straight_deg < 0.05);

    // The path alone: at every landing but the corner's, exactly over the landing (to round-off) at the
    // trunk's height above it; the corner's a quarter step along both legs' inward normals. (The bout's
    // last landing is left out: the bout eases out over it, so the trunk reaches it later.)
    BodyKinematics path(plan, path_only(BodyShape::chest()));
    for (size_t k = 0; k + 1 < steps.size(); ++k) {
        CAPTURE(k);
        const KinState s = path.at(steps[k]);
        const Eigen::Vector3d expected =
            k == corner ? feet[k] + Eigen::Vector3d(-0.25 * kStepM, 0.25 * kStepM, 0.0) : feet[k];
        CHECK((s.p_enu_m.head<2>() - expected.head<2>()).norm() < 1e-9);
        CHECK(std::fabs(s.p_enu_m.z() - 1.35 - feet[k].z()) < 1e-9);
    }
}

TEST_CASE("trunk on stairs: heights are the landings', the path within a quarter stride of them") {
    const Route route = builtin_route("stairs");
    const GaitPlan plan = plan_gait(route);
    BodyKinematics path(plan, path_only(BodyShape::chest()));
    const std::vector<double> steps = path.step_times_s();
    const std::vector<Eigen::Vector3d> feet = landings(plan);
    REQUIRE(feet.size() == steps.size());
    double worst_moved_m = 0.0, worst_below_m = 0.0;
    for (size_t k = 0; k + 1 < steps.size(); ++k) {
        CAPTURE(k);
        // Between the previous landing and this one: never far below the lower of the two.
        if (k > 0)
            for (int i = 0; i < 100; ++i) {
                const double t_s = steps[k - 1] + (steps[k] - steps[k - 1]) * i / 100.0;
                const double z_m = path.at(t_s).p_enu_m.z() - 1.35;
                worst_below_m = std::max(worst_below_m, std::min(feet[k - 1].z(), feet[k].z()) - z_m);
            }
        const KinState s = path.at(steps[k]);
        CHECK(std::fabs(s.p_enu_m.z() - 1.35 - feet[k].z()) < 1e-9);
        worst_moved_m = std::max(worst_moved_m, (s.p_enu_m.head<2>() - feet[k].head<2>()).norm());
    }
    std::printf(
        "trunk on stairs: at most %.3f m from its landing, at most %.4f m below a step's lower landing\n",
        worst_moved_m, worst_below_m);
    CHECK(worst_moved_m <
          0.25 * 2.0 * kStepM);  // 0.26 m: the stairwell's landing, one 1.5 m stride, at a U-turn
    // The height spline's own undershoot where a flight meets a level floor (heights are not smoothed).
    CHECK(worst_below_m < 0.02);
}
