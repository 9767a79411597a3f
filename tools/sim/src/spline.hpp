// SPDX-License-Identifier: Apache-2.0
// Cubic spline through (t_i, y_i) with zero slope at both ends (clamped):
// twice continuously differentiable, exact first and second derivatives.
#pragma once

#include <vector>

#include "profiles.hpp"

namespace pednav::sim::detail {

class ClampedSpline {
public:
    ClampedSpline() = default;
    // t strictly increasing, same size as y, at least two knots.
    ClampedSpline(std::vector<double> t, std::vector<double> y);
    Profile at(double t) const;  // clamps t to the knot range
    double t_begin() const { return t_.front(); }
    double t_end() const { return t_.back(); }

private:
    std::vector<double> t_, y_, m_;  // m_: second derivatives at the knots
};

}  // namespace pednav::sim::detail
