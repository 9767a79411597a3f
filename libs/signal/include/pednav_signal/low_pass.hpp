// SPDX-License-Identifier: Apache-2.0
// Low-pass filters in time, not in samples: each update uses the interval to
// the previous sample, so the same cut-off holds at 50 or 500 Hz and on the
// jittered sample times of Android sensors.
//
// FirstOrderLowPass is the exact discretisation of dy/dt = (x - y) / tau for
// an input held over the interval: y += (1 - exp(-dt / tau)) (x - y).
// SecondOrderLowPass is two of them in cascade with the same tau (critically
// damped, no overshoot on a step input); its -3 dB frequency is
// sqrt(sqrt(2) - 1) = 0.644 of one stage's 1 / (2 pi tau), and
// second_order_tau_s() gives the tau for a wanted -3 dB frequency.
#pragma once

#include <cmath>
#include <cstdint>

namespace pednav::signal {

class FirstOrderLowPass {
public:
    FirstOrderLowPass() = default;
    explicit FirstOrderLowPass(double tau_s) : tau_s_(tau_s) {}

    // The first sample sets the output; tau_s <= 0 passes the input through.
    double push(int64_t t_ns, double x) {
        if (!started_ || tau_s_ <= 0.0) {
            started_ = true;
        } else {
            const int64_t dt_ns = t_ns - t_ns_;
            if (dt_ns != dt_ns_) {  // exp only when the interval changes
                dt_ns_ = dt_ns;
                alpha_ = dt_ns > 0 ? 1.0 - std::exp(-static_cast<double>(dt_ns) * 1e-9 / tau_s_) : 0.0;
            }
            y_ += alpha_ * (x - y_);
            t_ns_ = t_ns;
            return y_;
        }
        y_ = x;
        t_ns_ = t_ns;
        return y_;
    }
    double value() const { return y_; }
    bool started() const { return started_; }
    void reset() { started_ = false, dt_ns_ = -1, y_ = 0.0; }

private:
    double tau_s_ = 0.0;
    bool started_ = false;
    int64_t t_ns_ = 0, dt_ns_ = -1;
    double alpha_ = 0.0, y_ = 0.0;
};

// tau of each stage of SecondOrderLowPass for a -3 dB frequency of cutoff_hz.
inline double second_order_tau_s(double cutoff_hz) {
    return cutoff_hz > 0.0 ? std::sqrt(std::sqrt(2.0) - 1.0) / (2.0 * M_PI * cutoff_hz) : 0.0;
}

class SecondOrderLowPass {
public:
    SecondOrderLowPass() = default;
    // cutoff_hz: the cascade's -3 dB frequency; 0 passes the input through.
    explicit SecondOrderLowPass(double cutoff_hz)
        : a_(second_order_tau_s(cutoff_hz)), b_(second_order_tau_s(cutoff_hz)) {}
    double push(int64_t t_ns, double x) { return b_.push(t_ns, a_.push(t_ns, x)); }
    double value() const { return b_.value(); }
    void reset() { a_.reset(), b_.reset(); }
    // Group delay at low frequencies, s: 2 tau.
    static double delay_s(double cutoff_hz) { return 2.0 * second_order_tau_s(cutoff_hz); }

private:
    FirstOrderLowPass a_, b_;
};

}  // namespace pednav::signal
