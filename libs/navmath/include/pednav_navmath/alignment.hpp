// SPDX-License-Identifier: Apache-2.0
// Alignment of a still sensor: the attitude from the measured specific force
// (gravity) and a heading, and the tilt-compensated magnetometer heading, for
// any orientation of the sensor, in the convention of heading_of().
#pragma once

#include <cmath>

#include "heading.hpp"
#include "so3.hpp"

namespace pednav::navmath {

// The level frame that level_attitude() and magnetic_heading() share: h is the
// body x axis projected on the level plane, or the body y axis when x is within
// about 6 deg of vertical (up_b.x^2 >= 0.99, the rule heading_of() uses:
// r00^2 + r10^2 = 1 - up_b.x^2), l = up x h is level and left of h, and
// offset is what heading_of() adds back for h (0, or -90 deg for the y axis).
struct LevelAxes {
    Vec3 h, l;
    double offset;
};
inline LevelAxes level_axes(const Vec3& up_b) {
    const bool x_vertical = up_b.x() * up_b.x() >= 0.99;
    const Vec3 ref = x_vertical ? Vec3::UnitY() : Vec3::UnitX();
    LevelAxes a;
    a.h = (ref - ref.dot(up_b) * up_b).normalized();
    a.l = up_b.cross(a.h);
    a.offset = x_vertical ? -M_PI / 2.0 : 0.0;
    return a;
}

// Attitude whose body "up" is the measured specific force at rest and whose
// heading_of() is `heading_rad` (clockwise from north): the level axis h of
// level_axes() points at heading_rad + offset. Works for any sensor orientation.
inline Quat level_attitude(const Vec3& f_body_at_rest, double heading_rad) {
    const Vec3 up_b = f_body_at_rest.normalized();
    const LevelAxes a = level_axes(up_b);
    const double psi = heading_rad + a.offset;
    // h points at azimuth psi: E = sin(psi) h - cos(psi) l, N = cos(psi) h + sin(psi) l.
    Mat3 r_enu_from_body;
    r_enu_from_body.row(0) = (std::sin(psi) * a.h - std::cos(psi) * a.l).transpose();
    r_enu_from_body.row(1) = (std::cos(psi) * a.h + std::sin(psi) * a.l).transpose();
    r_enu_from_body.row(2) = up_b.transpose();
    Quat q(r_enu_from_body);
    q.normalize();
    return q;
}

// Tilt-compensated magnetic heading (clockwise from magnetic north), in the
// convention of heading_of(): the field is projected on the level plane of
// level_axes(). Replaces the garbled foot-imu-zupt-zaru-ekf eq. (3)-(5) (see
// ERRATA.md); add the declination (east positive) to get true heading.
inline double magnetic_heading(const Vec3& f_body_at_rest, const Vec3& mag_body) {
    const LevelAxes a = level_axes(f_body_at_rest.normalized());
    // Field north N = cos(psi) h + sin(psi) l  =>  m.h = B cos(psi), m.l = B sin(psi).
    return std::atan2(mag_body.dot(a.l), mag_body.dot(a.h)) - a.offset;
}

}  // namespace pednav::navmath
