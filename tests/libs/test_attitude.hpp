// SPDX-License-Identifier: Apache-2.0
// The attitude of a test: R_enu_from_body from heading, pitch and roll, for
// the navmath and zupt_ins tests.
#pragma once

#include <cmath>

#include <Eigen/Geometry>

namespace pednav::test {

constexpr double kDeg = M_PI / 180.0;

// R_enu_from_body from heading (clockwise from north), pitch (nose up) and roll.
inline Eigen::Matrix3d attitude(double heading, double pitch, double roll) {
    const double yaw = M_PI / 2 - heading;  // ENU yaw of the body x axis
    return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(-pitch, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

}  // namespace pednav::test
