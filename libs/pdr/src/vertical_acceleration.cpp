// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr/vertical_acceleration.hpp"

#include <cmath>

namespace pednav::pdr {

double VerticalAcceleration::push(int64_t t_ns, const double a[3]) {
    dt_s_ = started_ ? static_cast<double>(t_ns - t_last_ns_) * 1e-9 : 0.0;
    if (!started_) {
        for (int i = 0; i < 3; ++i) g_lp_[i] = a[i];
        started_ = true;
    } else {
        const double k = 1.0 - std::exp(-dt_s_ / tau_s_);
        for (int i = 0; i < 3; ++i) g_lp_[i] += k * (a[i] - g_lp_[i]);
    }
    t_last_ns_ = t_ns;
    g_ = std::sqrt(g_lp_[0] * g_lp_[0] + g_lp_[1] * g_lp_[1] + g_lp_[2] * g_lp_[2]);
    return g_ > 0 ? (a[0] * g_lp_[0] + a[1] * g_lp_[1] + a[2] * g_lp_[2]) / g_ - g_ : 0.0;
}

double VerticalAcceleration::along_vertical(const double v[3]) const {
    return g_ > 0 ? (v[0] * g_lp_[0] + v[1] * g_lp_[1] + v[2] * g_lp_[2]) / g_ : 0.0;
}

}  // namespace pednav::pdr
