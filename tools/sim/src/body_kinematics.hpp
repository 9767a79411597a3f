// SPDX-License-Identifier: Apache-2.0
// Chest- or waist-mounted sensor trajectory: forward progression through the
// walk's step points (a clamped cubic spline per walking bout), vertical bounce
// at the step frequency, lateral sway at half of it, small pitch and roll
// oscillations, standing still (and turning on the spot) during pauses.
#pragma once

#include <vector>

#include "gait_plan.hpp"
#include "kinematics.hpp"
#include "spline.hpp"

namespace pednav::sim::detail {

struct BodyShape {
    double height_m = 1.35;    // sensor above the floor
    double bounce_m = 0.02;    // vertical amplitude (peak-to-peak twice this)
    double sway_m = 0.02;      // lateral amplitude at half the step frequency
    double pitch_rad = 0.035;  // pitch oscillation amplitude at the step frequency
    double roll_rad = 0.03;    // roll oscillation amplitude at half the step frequency
    static BodyShape chest() { return {}; }
    static BodyShape waist() { return {1.0, 0.025, 0.025, 0.025, 0.04}; }
};

class BodyKinematics {
public:
    BodyKinematics(const GaitPlan& plan, BodyShape shape);
    KinState at(double t_s);
    const BodyShape& shape() const { return shape_; }
    const std::vector<double>& step_times_s() const { return steps_; }

private:
    struct Span {  // a pause (standing, maybe turning) or a walking bout
        double t0 = 0.0, t1 = 0.0;
        bool walking = false;
        Eigen::Vector3d p = Eigen::Vector3d::Zero();  // pause: where
        double yaw0 = 0.0, yaw1 = 0.0;                // pause: turn from yaw0 to yaw1
        int segment = 0;
        std::vector<int> segment_at_knot;
        std::vector<double> knot_t;
        ClampedSpline x, y, z, yaw, phase;  // bout
        double ramp_in_s = 0.5, ramp_out_s = 0.5;
    };
    BodyShape shape_;
    std::vector<Span> spans_;
    std::vector<double> steps_;
    size_t cursor_ = 0;
};

}  // namespace pednav::sim::detail
