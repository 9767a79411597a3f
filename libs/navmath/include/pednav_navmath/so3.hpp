// SPDX-License-Identifier: Apache-2.0
// Rotations: skew matrices, the rotation vector exponential and logarithm,
// the Cayley transform, and unit quaternion products and rotations with the
// bits of Eigen's. Frames: navigation ENU, body = the sensor's own
// right-handed axes; quaternions are Hamilton, w first (Eigen's storage order
// differs, its constructor takes w first).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "angles.hpp"

namespace pednav::navmath {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// skew(w) v = w x v.  foot-imu-zupt-zaru-ekf eq. (9), as corrected in ERRATA.md.
inline Mat3 skew(const Vec3& w) {
    Mat3 s;
    s << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
    return s;
}

// Unit quaternion of the rotation vector `r` (axis * angle, rad).
inline Quat quat_exp(const Vec3& r) {
    const double a2 = r.squaredNorm();
    double s, c;
    if (a2 < 1e-2) {
        // Taylor series of sin(a/2)/a and cos(a/2); below 0.1 rad (every
        // sample of a walk) the first omitted terms are under 1e-16.
        s = 0.5 + a2 * (-1.0 / 48.0 + a2 * (1.0 / 3840.0 + a2 * (-1.0 / 645120.0)));
        c = 1.0 + a2 * (-1.0 / 8.0 + a2 * (1.0 / 384.0 + a2 * (-1.0 / 46080.0 + a2 * (1.0 / 10321920.0))));
    } else {
        const double a = std::sqrt(a2);
        s = std::sin(0.5 * a) / a;
        c = std::cos(0.5 * a);
    }
    return Quat(c, s * r.x(), s * r.y(), s * r.z());
}

// 1 / sqrt(n2) for a quaternion far from unit length (off the per-sample
// path, kept out of line so that the common case stays one branch); a zero or
// NaN norm gives 1, which leaves the quaternion as it is (an infinite one
// gives 0, and the quaternion NaN).
#if defined(__GNUC__)
__attribute__((noinline, cold))
#elif defined(_MSC_VER)
__declspec(noinline)
#endif
inline double far_unit_length_scale(double n2) {
    return n2 > 0 ? 1.0 / std::sqrt(n2) : 1.0;
}

// The factor that brings a quaternion of squared norm n2 back to unit length
// after a product of unit quaternions (n2 = 1 + e with e of a few ulp): one
// Newton step (3 - n2) / 2, accurate to O(e^2), without the square root and
// division on the per-sample path. Farther from unit length 1 / sqrt(n2)
// (within an ulp of normalize()).
inline double unit_length_scale(double n2) {
    if (std::abs(n2 - 1.0) < 1e-6) return 0.5 * (3.0 - n2);
    return far_unit_length_scale(n2);
}

// q scaled back to unit length (unit_length_scale).
inline void renormalize(Quat& q) { q.coeffs() *= unit_length_scale(q.squaredNorm()); }

// q.toRotationMatrix() * v with the same bits, from q's entries (Eigen's
// expressions for the matrix, and its order for the product: rows 0 and 1 as
// one vector of two accumulated column by column, row 2 as a sum split in
// halves): the product of a matrix just built on the stack reads its columns
// back with loads that straddle the stores that wrote them, which the store
// buffer cannot forward.
inline Vec3 rotate(const Quat& q, const Vec3& v) {
    const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
    const double tx = 2 * x, ty = 2 * y, tz = 2 * z;
    const double twx = tx * w, twy = ty * w, twz = tz * w;
    const double txx = tx * x, txy = ty * x, txz = tz * x;
    const double tyy = ty * y, tyz = tz * y, tzz = tz * z;
    const double vx = v.x(), vy = v.y(), vz = v.z();
    return Vec3(((1 - (tyy + tzz)) * vx + (txy - twz) * vy) + (txz + twy) * vz,
                ((txy + twz) * vx + (1 - (txx + tzz)) * vy) + (tyz - twx) * vz,
                (txz - twy) * vx + ((tyz + twx) * vy + (1 - (txx + tyy)) * vz));
}

// a * b for unit quaternions, brought back to unit length as renormalize()
// does, all in scalars: the vectorized product and norm load the quaternions
// as pairs of doubles, and a pair just written as two scalars (quat_exp's
// result, the previous product) cannot be forwarded from the store buffer,
// a stall of tens of cycles per sample.
inline Quat quat_mul_unit(const Quat& a, const Quat& b) {
    const double aw = a.w(), ax = a.x(), ay = a.y(), az = a.z();
    const double bw = b.w(), bx = b.x(), by = b.y(), bz = b.z();
    double w = aw * bw - ax * bx - ay * by - az * bz;
    double x = aw * bx + ax * bw + ay * bz - az * by;
    double y = aw * by + ay * bw + az * bx - ax * bz;
    double z = aw * bz + az * bw + ax * by - ay * bx;
    const double k = unit_length_scale((w * w + x * x) + (y * y + z * z));
    return Quat(k * w, k * x, k * y, k * z);
}

// Rotation vector of the unit quaternion q (angle in [0, pi]).
inline Vec3 quat_log(const Quat& q) {
    const Vec3 v(q.x(), q.y(), q.z());
    const double n = v.norm();
    const double w = q.w();
    if (n < 1e-12) return 2.0 * v / (w < 0 ? -1.0 : 1.0);
    double angle = 2.0 * atan2_fast(n, std::abs(w));
    return (w < 0 ? -angle : angle) * v / n;
}

// Cayley (Pade 1/1) transform of the rotation vector r:
// (I - skew(r)/2)^-1 (I + skew(r)/2). foot-imu-zupt-zaru-ekf eq. (8), (14)
// as corrected in ERRATA.md. Exact to second order in |r|.
inline Mat3 cayley(const Vec3& r) {
    const Mat3 s = 0.5 * skew(r);
    return (Mat3::Identity() - s).inverse() * (Mat3::Identity() + s);
}

}  // namespace pednav::navmath
