// SPDX-License-Identifier: Apache-2.0
// The path of the trunk (chest, pelvis, a phone held in front) through a
// walking bout: the centre of mass does not pass over every foot placement,
// it travels a smoothed version of them and rounds a corner. Each interior
// knot's horizontal position is replaced by (p[k-1] + 2 p[k] + p[k+1]) / 4
// (a binomial smoothing of the landings); the bout's first and last knots are
// kept, so the trunk starts and stops where it stands. A straight, evenly
// stepped stretch is a fixed point of the rule and stays where it is (to
// round-off); at a 90 deg corner taken on a footprint the corner's knot moves
// a quarter step back along the first leg and a quarter step along the second
// (0.25 m towards the inside of the turn at the nominal 0.7 m step).
//
// Heights are not smoothed: the trunk rides on the stance leg, on the stair
// it stands on. Smoothed like the horizontal, the knot at the top of a flight
// would sit a quarter of a riser below the top stair.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace pednav::sim::detail {

std::vector<Eigen::Vector3d> trunk_knots(const std::vector<Eigen::Vector3d>& landings_enu_m);

}  // namespace pednav::sim::detail
