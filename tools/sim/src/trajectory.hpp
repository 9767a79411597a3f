// SPDX-License-Identifier: Apache-2.0
// A body trajectory the sensor model samples: one implementation per mount.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "gait_plan.hpp"
#include "kinematics.hpp"

namespace pednav::sim::detail {

class Trajectory {
public:
    virtual ~Trajectory() = default;
    // Exact state at t_s; calls come with non-decreasing times.
    virtual KinState at(double t_s) = 0;
    // Height of the sensor above the floor it walks on, when standing.
    virtual double height_above_floor_m() const = 0;
    // Step events: foot: each landing of the instrumented foot; chest/waist: every step.
    virtual std::vector<double> step_times_s() const = 0;
};

// "foot", "chest", "handheld" or "waist"; throws std::runtime_error otherwise.
// surge_m: the body's forward oscillation (BodyShape::surge_m); NaN = the mount's own.
std::unique_ptr<Trajectory> make_trajectory(const std::string& mount, const GaitPlan& plan,
                                            double heel_strike_mps2 = 0.0, double surge_m = NAN);

}  // namespace pednav::sim::detail
