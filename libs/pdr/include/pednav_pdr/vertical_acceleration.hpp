// SPDX-License-Identifier: Apache-2.0
// The vertical acceleration of a body-worn sensor at any tilt: the gravity
// direction u is the specific force low-passed with a time constant (its
// mean over a few steps is gravity: the sensor's tilt is never assumed), and
//
//   a_v = f . u - |g_lp|
//
// (the norm of the low-pass also absorbs an accelerometer scale error). The
// rate of turn about the vertical is w . u. Used by the waist step detector
// and by anything that needs the same signal (the pelvis' rise over a step).
#pragma once

#include <cmath>
#include <cstdint>

namespace pednav::pdr {

class VerticalAcceleration {
public:
    // time_constant_s > 0.
    explicit VerticalAcceleration(double time_constant_s) : tau_s_(time_constant_s) {}

    // One sample of the specific force (sensor axes, m/s^2): returns a_v.
    // The first sample starts the low-pass.
    double push(int64_t t_ns, const double f_mps2[3]) {
        dt_s_ = started_ ? static_cast<double>(t_ns - t_last_ns_) * 1e-9 : 0.0;
        if (!started_) {
            for (int i = 0; i < 3; ++i) g_lp_[i] = f_mps2[i];
            started_ = true;
        } else {
            const double k = 1.0 - std::exp(-dt_s_ / tau_s_);
            for (int i = 0; i < 3; ++i) g_lp_[i] += k * (f_mps2[i] - g_lp_[i]);
        }
        t_last_ns_ = t_ns;
        g_ = std::sqrt(g_lp_[0] * g_lp_[0] + g_lp_[1] * g_lp_[1] + g_lp_[2] * g_lp_[2]);
        return g_ > 0 ? (f_mps2[0] * g_lp_[0] + f_mps2[1] * g_lp_[1] + f_mps2[2] * g_lp_[2]) / g_ - g_ : 0.0;
    }
    // A vector (a gyro sample) projected on the vertical of the last push.
    double along_vertical(const double v[3]) const {
        return g_ > 0 ? (v[0] * g_lp_[0] + v[1] * g_lp_[1] + v[2] * g_lp_[2]) / g_ : 0.0;
    }
    // Time since the sample before the last push, s (0 after the first).
    double dt_s() const { return dt_s_; }
    void reset() { started_ = false; }

private:
    double tau_s_;
    bool started_ = false;
    int64_t t_last_ns_ = 0;
    double dt_s_ = 0;
    double g_lp_[3] = {0, 0, 0};
    double g_ = 0;
};

}  // namespace pednav::pdr
