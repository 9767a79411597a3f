// SPDX-License-Identifier: Apache-2.0
// The trunk faces along its path (the pelvis' heading follows the tangent of
// the centre of mass' path): its yaw is the direction of the path's
// horizontal velocity, sampled at every knot and in the middle of every step
// and unwrapped, for a clamped cubic spline to interpolate. At the bout's
// first and last knots the path is at rest (the splines' zero end slopes), so
// there the yaw is the chord to the neighbouring knot; where the path stops
// inside a bout (it turns back on itself) the chord through the neighbours,
// or the sample before.
//
// Samples at the knots alone would not do: at a corner the path turns mostly
// around one knot, and a cubic through the knots' directions turns early, so
// that over the step into a 90 deg corner the mean yaw would miss the step's
// chord by 6.4 deg (1.3 deg with the mid-step samples; tests/sim,
// trunk_corner_test.cpp).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "spline.hpp"

namespace pednav::sim::detail {

struct HeadingSamples {
    std::vector<double> t_s;      // the knots' times and the steps' middles, increasing
    std::vector<double> yaw_rad;  // counter-clockwise from east, unwrapped from yaw_before_rad
};

// knot_t_s and knots_enu_m: the bout's knots (at least two); x, y: the path's splines through them.
HeadingSamples path_heading(const std::vector<double>& knot_t_s,
                            const std::vector<Eigen::Vector3d>& knots_enu_m, const ClampedSpline& x,
                            const ClampedSpline& y, double yaw_before_rad);

}  // namespace pednav::sim::detail
