// SPDX-License-Identifier: Apache-2.0
// The walking direction of an upper-body sensor from its attitude: the
// heading (clockwise from north) of one of its body axes projected level,
// plus a fixed offset between that axis and the way the walker goes (a phone
// held turned in the hand, a chest sensor mounted askew).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

namespace pednav::pdr {

// A body axis, signed: x, -x, y, -y, z, -z.
struct BodyAxis {
    int index = 0;     // 0, 1, 2
    double sign = 1.0; // +1 or -1
};

inline BodyAxis parse_body_axis(const std::string& name) {
    if (name.size() == 1 && name[0] >= 'x' && name[0] <= 'z') return {name[0] - 'x', 1.0};
    if (name.size() == 2 && name[0] == '-' && name[1] >= 'x' && name[1] <= 'z') return {name[1] - 'x', -1.0};
    throw std::invalid_argument("body axis must be x, -x, y, -y, z or -z, not " + name);
}

// Heading of the body axis under q_enu_from_body (w, x, y, z), clockwise from
// north, rad; NaN when the axis is within about 6 deg of vertical (its level
// projection has no direction).
inline double axis_heading_rad(const double q[4], BodyAxis axis) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    double e, n;  // the axis's east and north components: column `index` of R
    switch (axis.index) {
        case 0: e = 1 - 2 * (y * y + z * z), n = 2 * (x * y + w * z); break;
        case 1: e = 2 * (x * y - w * z), n = 1 - 2 * (x * x + z * z); break;
        default: e = 2 * (x * z + w * y), n = 2 * (y * z - w * x); break;
    }
    e *= axis.sign, n *= axis.sign;
    if (e * e + n * n < 0.01) return NAN;
    return std::atan2(e, n);
}

}  // namespace pednav::pdr
