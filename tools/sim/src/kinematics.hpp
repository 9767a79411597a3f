// SPDX-License-Identifier: Apache-2.0
// The exact state of the simulated body (foot, chest or pelvis) at one instant,
// before the sensor mounting rotation.
#pragma once

#include <cmath>

#include <Eigen/Dense>

namespace pednav::sim::detail {

struct KinState {
    Eigen::Vector3d p_enu_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d v_enu_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d a_enu_mps2 = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R_enu_body = Eigen::Matrix3d::Identity();
    Eigen::Vector3d w_body_radps = Eigen::Vector3d::Zero();  // angular rate in body axes
    double yaw_enu_rad = 0.0;                                // walking direction, counter-clockwise from east
    int stance = 1;
    int segment = 0;  // route segment (index of its start waypoint)
};

// An angle wrapped into [-pi, pi].
inline double wrap_pi(double a) {
    while (a > M_PI) a -= 2.0 * M_PI;
    while (a < -M_PI) a += 2.0 * M_PI;
    return a;
}

// R = Rz(yaw) Ry(pitch) Rx(roll) and the body angular rate from the angle rates.
inline void euler_zyx(double yaw, double pitch, double roll, double dyaw, double dpitch, double droll,
                      Eigen::Matrix3d& R_enu_body, Eigen::Vector3d& w_body) {
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d Ry = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const Eigen::Matrix3d Rx = Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()).toRotationMatrix();
    R_enu_body = Rz * Ry * Rx;
    w_body = Rx.transpose() *
                 (Ry.transpose() * Eigen::Vector3d(0.0, 0.0, dyaw) + Eigen::Vector3d(0.0, dpitch, 0.0)) +
             Eigen::Vector3d(droll, 0.0, 0.0);
}

}  // namespace pednav::sim::detail
