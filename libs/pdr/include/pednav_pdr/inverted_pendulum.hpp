// SPDX-License-Identifier: Apache-2.0
// The inverted-pendulum step length (Zijlstra and Hof): in the single
// support phase the pelvis rides on the stance leg as on a pendulum of the
// leg's length l, so a rise h of the pelvis over the step means a forward
// travel of
//
//   L = 2 sqrt(2 l h - h^2)
//
// (the chord of the arc), times a constant K per walker (the double support
// phase and the foot's roll add to it). h comes from the vertical
// acceleration of a sensor at the pelvis (vertical_acceleration.hpp):
// integrated twice over the step, the step's mean removed before each
// integration (a step starts and ends at the same height and vertical
// speed), the range of the vertical position.
#pragma once

#include <cstddef>
#include <cstdint>

namespace pednav::pdr {

// 2 sqrt(2 l h - h^2), m; 0 for h <= 0, and 2 l for h >= l.
double inverted_pendulum_step_m(double leg_length_m, double pelvis_rise_m);

// The rise of the pelvis over one step: the range of the vertical position
// obtained from the samples (time order, trapezoids) as above, m; 0 for
// fewer than three samples.
double pelvis_rise_m(const int64_t* t_ns, const double* accel_v_mps2, size_t count);

}  // namespace pednav::pdr
