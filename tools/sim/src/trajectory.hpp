// SPDX-License-Identifier: Apache-2.0
// A body trajectory the sensor model samples: one implementation per mount.
#pragma once

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

// "foot", "chest" or "waist"; throws std::runtime_error otherwise.
std::unique_ptr<Trajectory> make_trajectory(const std::string& mount, const GaitPlan& plan,
                                            double heel_strike_mps2 = 0.0);

}  // namespace pednav::sim::detail
