// SPDX-License-Identifier: Apache-2.0
// Smooth one-dimensional profiles with exact derivatives, the building blocks
// of the simulated trajectories. Each returns value, first and second
// derivative with respect to its argument.
#pragma once

namespace pednav::sim::detail {

struct Profile {
    double f = 0.0, df = 0.0, ddf = 0.0;
};

// Rest-to-rest transition 0 -> 1 on [0, 1] with zero velocity, acceleration
// and jerk at both ends (7th-order minimum-snap polynomial); 0 before, 1 after.
inline Profile transition(double u) {
    if (u <= 0.0) return {0.0, 0.0, 0.0};
    if (u >= 1.0) return {1.0, 0.0, 0.0};
    const double u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u, u6 = u5 * u, u7 = u6 * u;
    return {35.0 * u4 - 84.0 * u5 + 70.0 * u6 - 20.0 * u7, 140.0 * u3 - 420.0 * u4 + 420.0 * u5 - 140.0 * u6,
            420.0 * u2 - 1680.0 * u3 + 2100.0 * u4 - 840.0 * u5};
}

// Bump 256 u^4 (1-u)^4 on [0, 1]: peak 1 at u = 0.5, zero with zero first,
// second and third derivatives at both ends (so that a trajectory built from
// it has continuous jerk and angular acceleration); 0 outside.
inline Profile bump(double u) {
    if (u <= 0.0 || u >= 1.0) return {0.0, 0.0, 0.0};
    const double g = u * (1.0 - u), dg = 1.0 - 2.0 * u;
    return {256.0 * g * g * g * g, 1024.0 * g * g * g * dg, 1024.0 * g * g * (3.0 * dg * dg - 2.0 * g)};
}

// Profile p evaluated at u = (x - x0) / width, derivatives taken with respect to x.
template <typename F>
inline Profile scaled(F profile, double x, double x0, double width) {
    Profile p = profile((x - x0) / width);
    p.df /= width;
    p.ddf /= width * width;
    return p;
}

}  // namespace pednav::sim::detail
