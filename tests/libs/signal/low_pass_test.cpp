// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <pednav_signal/low_pass.hpp>

using namespace pednav::signal;

namespace {

// Amplitude of SecondOrderLowPass(cutoff) for a sine of f_hz sampled at
// rate_hz, jittered by up to +-jitter of the interval (deterministic), after
// the start transient.
double gain(double cutoff_hz, double f_hz, double rate_hz, double jitter) {
    SecondOrderLowPass lp(cutoff_hz);
    double peak = 0;
    uint32_t lcg = 12345;
    for (int k = 0; k < static_cast<int>(20.0 * rate_hz); ++k) {
        lcg = lcg * 1664525u + 1013904223u;
        const double u = (lcg >> 8) / 16777216.0 * 2.0 - 1.0;
        const double t = (k + (k > 0 ? jitter * u : 0.0)) / rate_hz;
        const double y = lp.push(static_cast<int64_t>(std::llround(t * 1e9)), std::sin(2 * M_PI * f_hz * t));
        if (t > 10.0) peak = std::max(peak, std::fabs(y));
    }
    return peak;
}

}  // namespace

TEST_CASE("low-pass in time: the same -3 dB frequency at 50 and 500 Hz and on jittered samples") {
    for (double rate : {50.0, 100.0, 418.0, 500.0})
        for (double jitter : {0.0, 0.4}) {
            CAPTURE(rate);
            CAPTURE(jitter);
            CHECK(gain(3.0, 3.0, rate, jitter) == doctest::Approx(std::sqrt(0.5)).epsilon(0.03));
            CHECK(gain(3.0, 0.3, rate, jitter) > 0.99);
            // Two stages of 1 / sqrt(1 + (f / fs)^2), fs = 1 / (2 pi tau) = fc / 0.644: 0.0235 at 10 fc
            // (sampled above 100 Hz; jitter adds a little).
            if (rate > 100) {
                const double fs = 1.0 / (2 * M_PI * second_order_tau_s(3.0));
                const double expected = 1.0 / (1.0 + std::pow(30.0 / fs, 2));
                CHECK(expected == doctest::Approx(0.0235).epsilon(0.01));
                CHECK(gain(3.0, 30.0, rate, jitter) == doctest::Approx(expected).epsilon(jitter > 0 ? 0.5 : 0.05));
            }
        }
}

TEST_CASE("low-pass: first sample passes, a step settles without overshoot, tau 0 passes through") {
    FirstOrderLowPass a(0.5);
    CHECK(a.push(0, 2.0) == 2.0);
    // After one time constant of a unit step: 1 - e^-1 of the way.
    double y = 0;
    for (int k = 1; k <= 100; ++k) y = a.push(static_cast<int64_t>(k) * 5000000, 3.0);
    CHECK(y == doctest::Approx(2.0 + (1.0 - std::exp(-1.0))).epsilon(1e-9));
    SecondOrderLowPass b(2.0);
    b.push(0, 0.0);
    double maxv = 0;
    for (int k = 1; k < 2000; ++k) maxv = std::max(maxv, b.push(static_cast<int64_t>(k) * 1000000, 1.0));
    CHECK(maxv <= 1.0);
    CHECK(maxv > 0.999);
    FirstOrderLowPass none(0.0);
    none.push(0, 1.0);
    CHECK(none.push(1000, 7.0) == 7.0);
}
