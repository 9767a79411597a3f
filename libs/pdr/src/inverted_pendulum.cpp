// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr/inverted_pendulum.hpp"

#include <algorithm>
#include <cmath>

namespace pednav::pdr {

double inverted_pendulum_step_m(double l, double h) {
    if (!(h > 0)) return 0.0;
    if (h >= l) return 2.0 * l;
    return 2.0 * std::sqrt(2.0 * l * h - h * h);
}

double pelvis_rise_m(const int64_t* t_ns, const double* a, size_t n) {
    if (n < 3) return 0.0;
    const double span_s = static_cast<double>(t_ns[n - 1] - t_ns[0]) * 1e-9;
    if (!(span_s > 0)) return 0.0;
    // Mean acceleration (trapezoids), then the vertical speed without it.
    double a_mean = 0.0;
    for (size_t k = 1; k < n; ++k)
        a_mean += 0.5 * (a[k] + a[k - 1]) * static_cast<double>(t_ns[k] - t_ns[k - 1]) * 1e-9;
    a_mean /= span_s;
    // v at each sample (v = 0 at the first), and its mean over the step.
    double v = 0.0, v_mean = 0.0;
    double v_prev = 0.0;
    for (size_t k = 1; k < n; ++k) {
        const double dt = static_cast<double>(t_ns[k] - t_ns[k - 1]) * 1e-9;
        v = v_prev + (0.5 * (a[k] + a[k - 1]) - a_mean) * dt;
        v_mean += 0.5 * (v + v_prev) * dt;
        v_prev = v;
    }
    v_mean /= span_s;
    // The position with the speed's mean removed; its range.
    double z = 0.0, z_min = 0.0, z_max = 0.0;
    v_prev = 0.0;
    for (size_t k = 1; k < n; ++k) {
        const double dt = static_cast<double>(t_ns[k] - t_ns[k - 1]) * 1e-9;
        v = v_prev + (0.5 * (a[k] + a[k - 1]) - a_mean) * dt;
        z += (0.5 * (v + v_prev) - v_mean) * dt;
        z_min = std::min(z_min, z);
        z_max = std::max(z_max, z);
        v_prev = v;
    }
    return z_max - z_min;
}

}  // namespace pednav::pdr
