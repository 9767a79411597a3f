// SPDX-License-Identifier: Apache-2.0
#include "path_heading.hpp"

#include <algorithm>
#include <cmath>

#include "kinematics.hpp"

namespace pednav::sim::detail {

namespace {

constexpr double kStillMps = 1e-3;  // slower than this the path's direction is the chord's

}  // namespace

HeadingSamples path_heading(const std::vector<double>& knot_t_s,
                            const std::vector<Eigen::Vector3d>& knots_enu_m, const ClampedSpline& x,
                            const ClampedSpline& y, double yaw_before_rad) {
    const size_t n = knot_t_s.size();
    HeadingSamples h;
    double yaw_now = yaw_before_rad;
    const auto add = [&](double t_s, size_t lo, size_t hi) {
        const Eigen::Vector2d v(x.at(t_s).df, y.at(t_s).df);
        const Eigen::Vector2d chord = (knots_enu_m[hi] - knots_enu_m[lo]).head<2>();
        double yaw = yaw_now;
        if (v.norm() > kStillMps)
            yaw = std::atan2(v.y(), v.x());
        else if (chord.norm() > 1e-9)
            yaw = std::atan2(chord.y(), chord.x());
        yaw_now += wrap_pi(yaw - yaw_now);
        h.t_s.push_back(t_s);
        h.yaw_rad.push_back(yaw_now);
    };
    for (size_t k = 0; k < n; ++k) {
        add(knot_t_s[k], k == 0 ? 0 : k - 1, std::min(n - 1, k + 1));
        if (k + 1 < n) add(0.5 * (knot_t_s[k] + knot_t_s[k + 1]), k, k + 1);
    }
    return h;
}

}  // namespace pednav::sim::detail
