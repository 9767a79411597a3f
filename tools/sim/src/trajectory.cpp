// SPDX-License-Identifier: Apache-2.0
#include "trajectory.hpp"

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
                                            double heel_strike_mps2) {
    if (mount == "foot") {
        FootShape shape;
        shape.heel_strike_mps2 = heel_strike_mps2;
        return std::make_unique<FootTrajectory>(plan, shape);
    }
    if (mount == "chest") return std::make_unique<BodyTrajectory>(plan, BodyShape::chest());
    if (mount == "waist") return std::make_unique<BodyTrajectory>(plan, BodyShape::waist());
    throw std::runtime_error("sim: unknown mount '" + mount + "' (foot, chest or waist)");
}

}  // namespace pednav::sim::detail
