// SPDX-License-Identifier: Apache-2.0
// Foot-mounted sensor trajectory: flat and still in stance; heel-off and
// toe-off pitch, swing arc, heel strike (level floors only), foot flat.
#pragma once

#include "gait_plan.hpp"
#include "kinematics.hpp"

namespace pednav::sim::detail {

struct FootShape {
    double toe_off_pitch_rad = 55.0 * M_PI / 180.0;      // peak toes-down pitch (heel-off, toe-off)
    double heel_strike_pitch_rad = 25.0 * M_PI / 180.0;  // peak toes-up pitch before landing, level floors
    double stairs_pitch_rad = 25.0 * M_PI / 180.0;       // toes-down pitch on stairs (no heel strike)
    double roll_rad = 3.0 * M_PI / 180.0;                // eversion during swing
    double clearance_m = 0.12;                           // swing height above the straight line
    double stairs_clearance_m = 0.08;
    double heel_strike_mps2 =
        0.0;  // peak vertical acceleration of the landing transient, level floors (0: none)
};

class FootKinematics {
public:
    FootKinematics(const GaitPlan& plan, FootShape shape = {}) : plan_(plan), shape_(shape) {}
    // Times must be non-decreasing between calls (a cursor walks the phases).
    KinState at(double t_s);

private:
    const GaitPlan& plan_;
    FootShape shape_;
    size_t cursor_ = 0;
};

}  // namespace pednav::sim::detail
