// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <pednav_pdr/peak_step_detector.hpp>

#include "../plugin_defaults.hpp"

using namespace pednav::pdr;

namespace {

PeakStepConfig defaults() {
    static const pednav::test::PluginDefaults d("libpnp_peak_steps.so", "org.pednav.pdr.steps.peak");
    return peak_step_config(d);
}

struct Walk {
    double rate_hz = 100.0;
    double jitter = 0.0;       // fraction of the sample interval
    double cadence_hz = 1.8;
    double amplitude_mps2 = 2.0;
    double stand_s = 3.0;      // still before and after
    double walk_s = 10.0;
    double yaw_rate_radps = 0.0;
};

// A trunk's specific force: gravity along body z plus a vertical oscillation
// at the cadence (highest at each heel strike) with its second harmonic;
// standing still before and after the walking bout.
std::vector<StepEvent> detect(const Walk& w, PeakStepDetector& d, int* walking_peaks = nullptr) {
    std::vector<StepEvent> out;
    uint32_t lcg = 7;
    const double total = 2 * w.stand_s + w.walk_s;
    for (int k = 0; k < static_cast<int>(total * w.rate_hz); ++k) {
        lcg = lcg * 1664525u + 1013904223u;
        const double u = (lcg >> 8) / 16777216.0 * 2.0 - 1.0;
        const double t = (k + (k > 0 ? w.jitter * u : 0.0)) / w.rate_hz;
        const double tw = t - w.stand_s;
        const bool walking = tw > 0 && tw < w.walk_s;
        const double ph = 2 * M_PI * w.cadence_hz * tw;
        const double a = walking ? w.amplitude_mps2 * (std::cos(ph) + 0.3 * std::cos(2 * ph)) : 0.0;
        const double f[3] = {0.0, 0.0, 9.81 + a};
        const double g[3] = {0.0, 0.0, walking ? w.yaw_rate_radps : 0.0};
        d.push(static_cast<int64_t>(std::llround(t * 1e9)), f, g, [&](const StepEvent& e) { out.push_back(e); });
    }
    d.flush([&](const StepEvent& e) { out.push_back(e); });
    // Crests at k / cadence for tw in [0, walk_s]: the bout starts and ends on one.
    if (walking_peaks) *walking_peaks = static_cast<int>(std::floor(w.walk_s * w.cadence_hz)) + 1;
    return out;
}

int count(const std::vector<StepEvent>& e, int mode) {
    int n = 0;
    for (const StepEvent& s : e) n += s.motion_mode == mode;
    return n;
}

}  // namespace

TEST_CASE("peak steps: one step per heel strike at 50 to 500 Hz and on jittered samples") {
    for (double rate : {50.0, 100.0, 418.0, 500.0})
        for (double jitter : {0.0, 0.45}) {
            CAPTURE(rate);
            CAPTURE(jitter);
            Walk w;
            w.rate_hz = rate;
            w.jitter = jitter;
            PeakStepDetector d(defaults());
            int truth = 0;
            const std::vector<StepEvent> e = detect(w, d, &truth);
            const int walking = count(e, PN_STEP_MODE_STRAIGHT);
            CHECK(walking >= truth - 2);
            CHECK(walking <= truth);
            double period_sum = 0;
            int periods = 0;
            for (const StepEvent& s : e) {
                CHECK(s.t_start_ns < s.t_ns);
                // The steps within the bout (its first and last crests are half-formed).
                if (s.motion_mode != PN_STEP_MODE_STRAIGHT || s.t_start_ns * 1e-9 < w.stand_s + 0.1 ||
                    s.t_ns * 1e-9 > w.stand_s + w.walk_s - 0.1)
                    continue;
                CHECK(s.accel_max_mps2 > s.accel_min_mps2);
                CHECK(s.accel_max_mps2 - s.accel_min_mps2 == doctest::Approx(3.4).epsilon(0.25));
                period_sum += 1.0 / s.frequency_hz, ++periods;
            }
            REQUIRE(periods > 10);
            CHECK(period_sum / periods == doctest::Approx(1.0 / 1.8).epsilon(0.03));
            // The stand before and after: pauses (STATIC), each record after the previous one.
            CHECK(count(e, PN_STEP_MODE_STATIC) >= 2);
            for (size_t i = 1; i < e.size(); ++i) CHECK(e[i].t_start_ns >= e[i - 1].t_ns);
        }
}

TEST_CASE("peak steps: a steady turn makes TURNING steps, the barometer's climb UPSTAIRS") {
    Walk w;
    w.yaw_rate_radps = 0.6;  // 19 deg per step at 1.8 Hz
    PeakStepDetector d(defaults());
    const std::vector<StepEvent> e = detect(w, d);
    CHECK(count(e, PN_STEP_MODE_TURNING) >= 14);
    CHECK(count(e, PN_STEP_MODE_STRAIGHT) <= 2);
    for (const StepEvent& s : e)
        if (s.motion_mode == PN_STEP_MODE_TURNING && s.frequency_hz > 0)
            CHECK(s.heading_change_rad == doctest::Approx(-0.6 / s.frequency_hz).epsilon(0.1));

    PeakStepDetector up(defaults());
    up.set_vertical_rate(0.3);
    const std::vector<StepEvent> climb = detect(Walk{}, up);
    CHECK(count(climb, PN_STEP_MODE_UPSTAIRS) >= 15);
    PeakStepDetector down(defaults());
    down.set_vertical_rate(-0.3);
    CHECK(count(detect(Walk{}, down), PN_STEP_MODE_DOWNSTAIRS) >= 15);
}

TEST_CASE("peak steps: cadence check, weak bumps, latency, bad configs") {
    Walk slow;  // 0.5 Hz: peaks further apart than max_step_s are not steps of a bout
    slow.cadence_hz = 0.5;
    PeakStepDetector d(defaults());
    const std::vector<StepEvent> e = detect(slow, d);
    for (const StepEvent& s : e)
        if (s.motion_mode != PN_STEP_MODE_STATIC) CHECK(s.frequency_hz >= 1.0 / defaults().max_step_s - 1e-9);
    Walk weak;
    weak.amplitude_mps2 = 0.1;
    PeakStepDetector w(defaults());
    CHECK(count(detect(weak, w), PN_STEP_MODE_STRAIGHT) == 0);
    CHECK(PeakStepDetector(defaults()).latency_ns() == static_cast<int64_t>(std::ceil(defaults().confirm_s * 1e9)));
    PeakStepConfig bad = defaults();
    bad.max_step_s = bad.min_step_s;
    CHECK_THROWS_AS(PeakStepDetector{bad}, std::invalid_argument);
    bad = defaults();
    bad.lowpass_hz = 0;
    CHECK_THROWS_AS(PeakStepDetector{bad}, std::invalid_argument);
}
