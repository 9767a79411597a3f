// SPDX-License-Identifier: Apache-2.0
// Gravity alignment and the tilt-compensated magnetometer heading.
#include <doctest/doctest.h>

#include <cmath>

#include <pednav_navmath/alignment.hpp>
#include <pednav_navmath/heading.hpp>

#include "../test_attitude.hpp"

using namespace pednav::navmath;
using pednav::test::attitude;
using pednav::test::kDeg;

TEST_CASE("level alignment and tilt-compensated magnetometer heading at several attitudes") {
    const double g = 9.81;
    const double dip = 64 * kDeg, field = 48.0;
    const Vec3 m_enu(0.0, field * std::cos(dip), -field * std::sin(dip));  // magnetic north, pointing down
    for (double heading : {0.0, 37.0, 135.0, -100.0, 179.0})
        // 75-83 deg: body x tilted 7-15 deg off vertical, still heading_of()'s x axis
        // case; -87 deg: within 6 deg of vertical, the y axis case.
        for (double pitch : {0.0, 20.0, -35.0, 60.0, 75.0, 80.0, 83.0, -87.0})
            for (double roll : {0.0, 25.0, -50.0, 170.0}) {  // 170 deg: the sensor upside down (z down)
                const Mat3 R = attitude(heading * kDeg, pitch * kDeg, roll * kDeg);
                const Vec3 f_body = R.transpose() * Vec3(0, 0, g);
                const Vec3 m_body = R.transpose() * m_enu;
                const Quat q(R);
                const double psi_true = heading_of(q);
                CHECK(std::abs(wrap_pi(magnetic_heading(f_body, m_body) - psi_true)) < 1e-9);
                const Quat qa = level_attitude(f_body, psi_true);
                CHECK(std::abs(wrap_pi(heading_of(qa) - psi_true)) < 1e-9);
                CHECK((qa.toRotationMatrix() - R).norm() < 1e-9);
            }
}
