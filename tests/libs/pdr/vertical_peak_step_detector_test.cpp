// SPDX-License-Identifier: Apache-2.0
// The waist step detector on synthetic walks: a sensor tilted on the belt,
// a vertical acceleration of one cycle per step, a turn, stairs (barometer).
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <pednav_geodesy/atmosphere.hpp>
#include <pednav_navmath/so3.hpp>
#include <pednav_pdr/vertical_peak_step_detector.hpp>

#include "../plugin_defaults.hpp"

using namespace pednav;

namespace {
pdr::VerticalPeakStepConfig defaults() {
    static const test::PluginDefaults d("libpnp_waist_peak.so", "org.pednav.waist.steps.peak");
    return pdr::vertical_peak_step_config(d);
}

struct Walk {
    double step_hz = 1.8, amplitude_mps2 = 2.0, yaw_rate_radps = 0.0, climb_mps = 0.0;
    int steps = 20;
    double still_s = 3.0;
    int weak_tail_steps = 0;  // the last steps this weak (a walker slowing to a stop)
    double weak_tail_amplitude_mps2 = 0.0;
};

// Standing still_s, walking `steps` steps, standing again; the sensor is
// rolled 40 deg and pitched -25 deg on the belt. Returns every event.
std::vector<pdr::VerticalStepEvent> run(const Walk& w, const pdr::VerticalPeakStepConfig& c) {
    pdr::VerticalPeakStepDetector det(c, 200.0);
    std::vector<pdr::VerticalStepEvent> events;
    auto out = [&](const pdr::VerticalStepEvent& e) { events.push_back(e); };
    const double rate = 100.0, walk_s = w.steps / w.step_hz, total_s = 2 * w.still_s + walk_s;
    const navmath::Quat mount = navmath::quat_exp(navmath::Vec3(40.0 * M_PI / 180, 0, 0)) *
                                navmath::quat_exp(navmath::Vec3(0, -25.0 * M_PI / 180, 0));
    double yaw = 0;
    for (int k = 0; k * (1.0 / rate) < total_s; ++k) {
        const double t = k / rate;
        const bool walking = t >= w.still_s && t < w.still_s + walk_s;
        const bool tail = t >= w.still_s + (w.steps - w.weak_tail_steps) / w.step_hz;
        const double amplitude = tail ? w.weak_tail_amplitude_mps2 : w.amplitude_mps2;
        const double a_v = walking ? amplitude * std::sin(2 * M_PI * w.step_hz * (t - w.still_s)) : 0.0;
        const double yaw_rate = walking ? w.yaw_rate_radps : 0.0;
        yaw += yaw_rate / rate;
        const navmath::Quat q = navmath::quat_exp(navmath::Vec3(0, 0, yaw)) * mount;  // ENU from sensor
        const navmath::Vec3 f = q.conjugate() * navmath::Vec3(0, 0, 9.81 + a_v);
        const navmath::Vec3 w_b = q.conjugate() * navmath::Vec3(0, 0, yaw_rate);
        const double a[3] = {f.x(), f.y(), f.z()}, g[3] = {w_b.x(), w_b.y(), w_b.z()};
        const int64_t t_ns = static_cast<int64_t>(std::llround(t * 1e9));
        if (k % 4 == 0) {
            const double z = walking ? w.climb_mps * (t - w.still_s) : (t < w.still_s ? 0.0 : w.climb_mps * walk_s);
            det.push_baro(t_ns, geodesy::standard_pressure_pa(z));
        }
        det.push_imu(t_ns, a, g, out);
    }
    det.flush(out);
    return events;
}

int count(const std::vector<pdr::VerticalStepEvent>& e, pdr::MotionMode m) {
    int n = 0;
    for (const auto& x : e) n += x.mode == m;
    return n;
}
int steps_of(const std::vector<pdr::VerticalStepEvent>& e) {
    int n = 0;
    for (const auto& x : e) n += x.mode != pdr::MotionMode::standing;
    return n;
}
}  // namespace

TEST_CASE("peak steps: one step per cycle of the vertical acceleration, whatever the tilt, at 1 to 2.5 Hz") {
    for (double hz : {1.0, 1.8, 2.5}) {
        Walk w;
        w.step_hz = hz;
        const auto e = run(w, defaults());
        CAPTURE(hz);
        // The first cycle starts from standing (no dip before its peak, C1)
        // and may be missed; every other one is a step.
        CHECK(steps_of(e) >= w.steps - 1);
        CHECK(steps_of(e) <= w.steps);
        CHECK(count(e, pdr::MotionMode::straight) == steps_of(e));
        CHECK(count(e, pdr::MotionMode::standing) == 1);  // the bout's end
        int full = 0;
        for (size_t i = 1; i + 2 < e.size(); ++i) {  // the steps inside the bout
            // (the 0.2 s moving average keeps 64 % of the amplitude at 2.5 Hz)
            full += e[i].accel_max_mps2 > 1.0 && e[i].accel_min_mps2 < -1.0 &&
                    std::abs(e[i].frequency_hz / hz - 1.0) < 0.05;
        }
        CHECK(full == static_cast<int>(e.size()) - 3);
    }
}

TEST_CASE("peak steps: C1 (amplitude) and C2 (cadence) reject sway and slow rocking") {
    Walk weak;
    weak.amplitude_mps2 = 0.1;  // below accel_max_threshold_mps2
    CHECK(steps_of(run(weak, defaults())) == 0);
    Walk slow;
    slow.step_hz = 0.5;  // 2 s between peaks: longer than max_step_interval_s
    CHECK(steps_of(run(slow, defaults())) == 0);
}

TEST_CASE("peak steps: C1 is a hysteresis: weaker steps continue a bout, and do not start one") {
    // +-0.12 m/s^2 after the 0.2 s average at 1.8 Hz (which keeps 77 % of
    // it): weaker than the thresholds that start a bout (0.15, -0.2),
    // stronger than those that continue one (0.1, -0.1).
    const double weak_mps2 = 0.156;
    Walk slowing;
    slowing.amplitude_mps2 = 0.4;  // a slow walk: the gravity low-pass keeps little of it
    slowing.weak_tail_steps = 3;
    slowing.weak_tail_amplitude_mps2 = weak_mps2;
    const pdr::VerticalPeakStepConfig c = defaults();
    CHECK(steps_of(run(slowing, c)) >= slowing.steps - 1);
    pdr::VerticalPeakStepConfig no_hysteresis = c;
    no_hysteresis.bout_accel_max_threshold_mps2 = c.accel_max_threshold_mps2;
    no_hysteresis.bout_accel_min_threshold_mps2 = c.accel_min_threshold_mps2;
    CHECK(steps_of(run(slowing, no_hysteresis)) <= slowing.steps - 1 - slowing.weak_tail_steps);
    Walk weak;
    weak.amplitude_mps2 = weak_mps2;  // a whole walk as weak: never a bout
    CHECK(steps_of(run(weak, c)) == 0);
    pdr::VerticalPeakStepConfig inverted = c;
    inverted.bout_accel_max_threshold_mps2 = c.accel_max_threshold_mps2 + 0.1;
    CHECK_THROWS_AS(pdr::VerticalPeakStepDetector(inverted, 200.0), std::invalid_argument);
}

TEST_CASE("peak steps: motion modes turning (gyro about the vertical) and up/down stairs (barometer)") {
    Walk turn;
    turn.yaw_rate_radps = 0.8;
    const auto et = run(turn, defaults());
    CHECK(count(et, pdr::MotionMode::turning) >= turn.steps - 1);
    double total_turn = 0;
    for (const auto& x : et) total_turn += x.heading_change_rad;
    // Clockwise positive: a counter-clockwise turn about up is negative.
    CHECK(total_turn == doctest::Approx(-0.8 * turn.steps / turn.step_hz).epsilon(0.1));

    Walk up;
    up.climb_mps = 0.3;  // 0.17 m per step at 1.8 Hz
    Walk down = up;
    down.climb_mps = -0.3;
    const auto eu = run(up, defaults()), ed = run(down, defaults());
    CHECK(count(eu, pdr::MotionMode::upstairs) >= up.steps - 3);
    CHECK(count(ed, pdr::MotionMode::downstairs) >= down.steps - 3);
    CHECK(count(eu, pdr::MotionMode::downstairs) == 0);
}
