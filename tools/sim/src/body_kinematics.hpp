// SPDX-License-Identifier: Apache-2.0
// Chest- or waist-mounted sensor trajectory: forward progression along the
// centre of mass' path, the walk's step points smoothed (trunk_path.hpp; a
// clamped cubic spline per walking bout), facing along that path
// (path_heading.hpp), vertical bounce at the step frequency, lateral sway at
// half of it, small pitch and roll oscillations, standing still (and turning
// on the spot) during pauses.
//
// The bounce follows the inverted pendulum: the stance leg (length l) swings
// the centre of mass over the stance foot through the centre of mass' own
// travel over the step, so the trunk rises by
//
//   h(L) = l - sqrt(l^2 - (L/2)^2)     (about L^2 / 8l)
//
// with L the horizontal length of the trunk's chord over the step, from one
// landing's knot of its smoothed path to the next (trunk_path.hpp), not the
// spacing of the feet. The two agree on straight, evenly stepped legs; over
// the two steps either side of a 90 deg corner the chord is 21 % shorter, and
// those steps bounce 38 % less at the nominal step. The bounce amplitude of
// each level step is bounce_m h(L) / h(L_nominal): a nominal step keeps
// bounce_m exactly, and with the gait plan's walk ratio (cadence proportional
// to the step) the vertical acceleration range over a step of a straight leg
// grows as L^4, which is what Weinberg's step-length model reads. Steps on
// stairs keep bounce_m. The amplitude is a clamped cubic spline of the step
// phase through each step's value at mid-step (phase k - 1/2 for step k), so
// position, velocity and acceleration stay exactly consistent.
#pragma once

#include <cmath>
#include <vector>

#include "gait_plan.hpp"
#include "kinematics.hpp"
#include "profiles.hpp"
#include "spline.hpp"

namespace pednav::sim::detail {

struct BodyShape {
    double height_m = 1.35;    // sensor above the floor
    double bounce_m = 0.02;    // vertical amplitude at the nominal step (peak-to-peak twice this)
    double sway_m = 0.02;      // lateral amplitude at half the step frequency
    double pitch_rad = 0.035;  // pitch oscillation amplitude at the step frequency
    double roll_rad = 0.03;    // roll oscillation amplitude at half the step frequency
    // Terms only the handheld mount has by default (0: off, and the other
    // mounts' trajectories stay bit for bit what they were):
    double surge_m = 0.0;          // forward oscillation at the step frequency, fastest at each landing
                                   // (the inverted pendulum: the trunk is lowest and fastest in double support)
    double pitch_offset_rad = 0.0; // constant pitch, negative = nose up (a phone tilted towards the face)
    double hand_sway_m = 0.0;      // the hand's own motion: lateral at half the step frequency, vertical at it
    double wobble_rad = 0.0;       // slow attitude wobble of the hand (yaw, pitch, roll), 0.23 to 0.61 Hz
    double leg_length_m = 0.9;     // the inverted pendulum's length, hip to floor (a walker of about 1.75 m)
    static BodyShape chest() { return {}; }
    static BodyShape waist() { return {1.0, 0.025, 0.025, 0.025, 0.04}; }
    // A phone held in front at 1.1 m, pitched 35 deg nose up, following the
    // trunk's bounce, sway and surge, with the hand's own motion on top.
    static BodyShape handheld() {
        BodyShape s{1.1, 0.02, 0.015, 0.02, 0.02};
        s.surge_m = 0.02;
        s.pitch_offset_rad = -35.0 * M_PI / 180.0;
        s.hand_sway_m = 0.008;
        s.wobble_rad = 0.03;
        return s;
    }
};

class BodyKinematics {
public:
    BodyKinematics(const GaitPlan& plan, BodyShape shape);
    KinState at(double t_s);
    const BodyShape& shape() const { return shape_; }
    const std::vector<double>& step_times_s() const { return steps_; }

private:
    bool has_hand_terms() const {
        return shape_.surge_m != 0.0 || shape_.pitch_offset_rad != 0.0 || shape_.hand_sway_m != 0.0 ||
               shape_.wobble_rad != 0.0;
    }
    void add_hand_attitude(double t_s, const Profile& yaw, const Profile& pitch, const Profile& roll,
                           KinState& k) const;
    struct Span {  // a pause (standing, maybe turning) or a walking bout
        double t0 = 0.0, t1 = 0.0;
        bool walking = false;
        Eigen::Vector3d p = Eigen::Vector3d::Zero();  // pause: where
        double yaw0 = 0.0, yaw1 = 0.0;                // pause: turn from yaw0 to yaw1
        int segment = 0;
        std::vector<int> segment_at_knot;
        std::vector<double> knot_t;
        ClampedSpline x, y, z, yaw, phase;  // bout (yaw on its own knots: path_heading.hpp)
        ClampedSpline bounce_scale;         // bout: the bounce amplitude over bounce_m, against the phase
        double ramp_in_s = 0.5, ramp_out_s = 0.5;
    };
    BodyShape shape_;
    std::vector<Span> spans_;
    std::vector<double> steps_;
    size_t cursor_ = 0;
};

}  // namespace pednav::sim::detail
