// Rotation helpers shared by the foot plugins: skew matrices, the rotation
// vector exponential and logarithm, and the level-frame alignment from a
// gravity direction and a heading. Frames: navigation ENU, body = the sensor's
// own right-handed axes; quaternions are Hamilton, w first (Eigen's storage
// order differs, its constructor takes w first).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace pednav::foot {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

// skew(w) v = w x v.  foot-imu-zupt-zaru-ekf eq. (9), as corrected in ERRATA.md.
inline Mat3 skew(const Vec3& w) {
    Mat3 s;
    s << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
    return s;
}

// atan2(y, x) without the libm call (which costs about 130 instructions):
// reduction to t = min(|x|, |y|) / max(|x|, |y|) in [0, 1], then t > 0.66 to
// (t - 1) / (t + 1) (atan t = pi/4 + atan((t - 1)/(t + 1))), and Cephes'
// rational approximation of atan on |t| <= 0.66 (relative error below
// 2e-16); the octant is restored with the low-order parts of pi/4, pi/2
// and pi. Within 1.1 ulp of libm's atan2 (4.5e-16 rad absolute); the same
// special values for (0, 0) and NaN (handed to libm).
inline double atan2_fast(double y, double x) {
    const double ay = std::abs(y), ax = std::abs(x);
    const bool swap = ay > ax;
    const double num = swap ? ax : ay, den = swap ? ay : ax;
    if (!(den > 0) || den == HUGE_VAL) return std::atan2(y, x);  // (0, 0), NaN, infinities
    double t = num / den;
    double base = 0.0, lo = 0.0;
    if (t > 0.66) {
        t = (t - 1.0) / (t + 1.0);
        base = M_PI_4;
        lo = 3.061616997868382943065e-17;  // pi/4 - M_PI_4
    }
    const double z = t * t, z2 = z * z;
    // Estrin's scheme (pairs of terms, then z^2): a shorter dependency chain than Horner's.
    const double p = ((-8.750608600031904122785e-1 * z - 1.615753718733365076637e1) * z2 +
                      (-7.500855792314704667340e1 * z - 1.228866684490136173410e2)) * z -
                     6.485021904942025371773e1;
    const double q = (z2 * (z + 2.485846490142306297962e1) + (1.650270098316988542046e2 * z +
                      4.328810604912902668951e2)) * z2 +
                     (4.853903996359136964868e2 * z + 1.945506571482613964425e2);
    double r = base + ((t * (z * p / q) + lo) + t);
    if (swap) r = (M_PI_2 - r) + 6.123233995736765886130e-17;  // + (pi/2 - M_PI_2)
    if (x < 0) r = (M_PI - r) + 1.224646799147353207173e-16;   // + (pi - M_PI)
    return std::signbit(y) ? -r : r;
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

inline double wrap_pi(double a) {
    a = std::fmod(a + M_PI, 2.0 * M_PI);
    if (a < 0) a += 2.0 * M_PI;
    return a - M_PI;
}

}  // namespace pednav::foot
