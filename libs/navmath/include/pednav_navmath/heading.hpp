// SPDX-License-Identifier: Apache-2.0
// The heading of an attitude: clockwise from north, of the body x axis
// projected on the level plane (the body y axis when x is near vertical).
#pragma once

#include "angles.hpp"
#include "so3.hpp"

namespace pednav::navmath {

// Heading, clockwise from north, of the body x axis projected on the level
// plane; falls back to the body y axis (minus 90 deg) when x is near vertical.
// Only the four entries of the rotation matrix it needs, computed with the
// same expressions as Eigen's toRotationMatrix().
inline double heading_of(const Quat& q_enu_from_body) {
    const double w = q_enu_from_body.w(), x = q_enu_from_body.x(), y = q_enu_from_body.y(),
                 z = q_enu_from_body.z();
    const double tx = 2 * x, ty = 2 * y, tz = 2 * z;
    const double twz = tz * w, txx = tx * x, txy = ty * x, tyy = ty * y, tzz = tz * z;
    const double r00 = 1 - (tyy + tzz), r10 = txy + twz;
    if (r00 * r00 + r10 * r10 > 0.01) return atan2_fast(r00, r10);
    const double r01 = txy - twz, r11 = 1 - (txx + tzz);
    return atan2_fast(r01, r11) + M_PI / 2.0;
}

// The same heading from R = q.toRotationMatrix() (the same bits: the four
// entries above are Eigen's expressions).
inline double heading_of(const Mat3& r_enu_from_body) {
    const double r00 = r_enu_from_body(0, 0), r10 = r_enu_from_body(1, 0);
    if (r00 * r00 + r10 * r10 > 0.01) return atan2_fast(r00, r10);
    return atan2_fast(r_enu_from_body(0, 1), r_enu_from_body(1, 1)) + M_PI / 2.0;
}

}  // namespace pednav::navmath
