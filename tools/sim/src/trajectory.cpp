// SPDX-License-Identifier: Apache-2.0
#include "trajectory.hpp"

#include <cmath>
#include <stdexcept>

#include "body_kinematics.hpp"
#include "foot_kinematics.hpp"

namespace pednav::sim::detail {

namespace {

class FootTrajectory : public Trajectory {
public:
    FootTrajectory(const GaitPlan& plan, const FootShape& shape) : plan_(plan), kin_(plan, shape) {}
    KinState at(double t_s) override { return kin_.at(t_s); }
    double height_above_floor_m() const override { return 0.0; }
    std::vector<double> step_times_s() const override { return plan_.landing_s; }

private:
    const GaitPlan& plan_;
    FootKinematics kin_;
};

class BodyTrajectory : public Trajectory {
public:
    BodyTrajectory(const GaitPlan& plan, const BodyShape& shape) : kin_(plan, shape) {}
    KinState at(double t_s) override { return kin_.at(t_s); }
    double height_above_floor_m() const override { return kin_.shape().height_m; }
    std::vector<double> step_times_s() const override { return kin_.step_times_s(); }

private:
    BodyKinematics kin_;
};

}  // namespace

std::unique_ptr<Trajectory> make_trajectory(const std::string& mount, const GaitPlan& plan,
                                            double heel_strike_mps2, double surge_m) {
    if (mount == "foot") {
        FootShape shape;
        shape.heel_strike_mps2 = heel_strike_mps2;
        return std::make_unique<FootTrajectory>(plan, shape);
    }
    BodyShape shape;
    if (mount == "chest")
        shape = BodyShape::chest();
    else if (mount == "waist")
        shape = BodyShape::waist();
    else if (mount == "handheld")
        shape = BodyShape::handheld();
    else
        throw std::runtime_error("sim: unknown mount '" + mount + "' (foot, chest, handheld or waist)");
    if (!std::isnan(surge_m)) shape.surge_m = surge_m;
    return std::make_unique<BodyTrajectory>(plan, shape);
}

}  // namespace pednav::sim::detail
