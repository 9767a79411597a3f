// SPDX-License-Identifier: Apache-2.0
// The simulated gait keeps the walk ratio and the trunk bounces as an
// inverted pendulum (docs/simulator.md, "Kinematics"): a level stride s times
// the nominal takes the nominal stride time over s, stairs keep their period;
// each level step's bounce is bounce_m times the pendulum's rise over the
// trunk's own chord over that step (landing to landing on its smoothed path)
// against the nominal step's, so on evenly stepped legs the vertical
// acceleration range of a step grows as its length to the fourth power (what
// Weinberg's model reads), and a corner step, over which the trunk travels
// less than the feet's spacing, bounces less.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>

#include <pednav_sim/simulate.hpp>

using namespace pednav::sim;

namespace {

constexpr double kStrideNominalM = 1.4;                    // the route's step_length_m 0.7, twice
constexpr double kStrideNominalS = kStrideNominalM / 1.3;  // at speed_mps 1.3
constexpr double kLegM = 0.9, kChestBounceM = 0.02, kChestHeightM = 1.35;
constexpr double kGravityMps2 = 9.80665;

// Along x: 10 nominal strides, one stride 20 % longer, 9 strides 5 % longer,
// 10 strides 5 % shorter (the segment's own stride counts: round(length /
// nominal stride)).
const double kStrideRatio[] = {1.0, 1.2, 1.05, 0.95};
const int kStrides[] = {10, 1, 9, 10};

Route straight_route() {
    Route r;
    r.name = "walk_ratio";
    r.start_still_s = 2.0;
    r.end_still_s = 2.0;
    Waypoint w;
    r.waypoints.push_back(w);
    for (int i = 0; i < 4; ++i) {
        w.enu_m[0] += kStrides[i] * kStrideRatio[i] * kStrideNominalM;
        r.waypoints.push_back(w);
    }
    return r;
}

SimOutput exact(const Route& route, const std::string& mount) {
    SimOptions o;
    o.mount = mount;
    o.rate_hz = 1000.0;
    o.sensor_errors = false;
    o.with_mag = o.with_baro = o.with_gnss = false;
    return simulate(route, o);
}

double pendulum_rise_m(double step_m) { return kLegM - std::sqrt(kLegM * kLegM - 0.25 * step_m * step_m); }

// The sensor's horizontal position at t_s: the truth sample at or before it, moved on by its velocity.
Eigen::Vector2d horizontal_at(const SimOutput& o, double t_s) {
    const TruthSample& s = o.truth[static_cast<size_t>(std::floor(t_s * o.rate_hz))];
    const double dt_s = t_s - s.t_s;
    return {s.pos_enu_m[0] + s.vel_enu_mps[0] * dt_s, s.pos_enu_m[1] + s.vel_enu_mps[1] * dt_s};
}

// Over step k (from landing k - 1 to landing k): the trunk's horizontal chord (the chest's sway is zero
// at each landing, so the chord is its path's), the highest point of the bounce above the walking
// height and the vertical acceleration's range.
struct StepBounce {
    double chord_m = 0.0, z_max_m = 0.0, accel_range_mps2 = 0.0;
};

StepBounce step_bounce(const SimOutput& o, size_t k) {
    const std::vector<double>& steps = o.step_times_s;
    StepBounce b;
    b.chord_m = (horizontal_at(o, steps[k]) - horizontal_at(o, steps[k - 1])).norm();
    const size_t i0 = static_cast<size_t>(std::llround(steps[k - 1] * o.rate_hz)),
                 i1 = static_cast<size_t>(std::llround(steps[k] * o.rate_hz));
    double z_max = -1e9, a_min = 1e9, a_max = -1e9;
    for (size_t i = i0; i <= i1; ++i) {
        const TruthSample& t = o.truth[i];
        z_max = std::max(z_max, t.pos_enu_m[2] - kChestHeightM);
        const Eigen::Quaterniond q(t.q_enu_from_body[0], t.q_enu_from_body[1], t.q_enu_from_body[2],
                                   t.q_enu_from_body[3]);
        const Eigen::Vector3d f(o.imu[i].accel_mps2[0], o.imu[i].accel_mps2[1], o.imu[i].accel_mps2[2]);
        const double a_up = (q * f).z() - kGravityMps2;
        a_min = std::min(a_min, a_up);
        a_max = std::max(a_max, a_up);
    }
    b.z_max_m = z_max;
    b.accel_range_mps2 = a_max - a_min;
    return b;
}

// The segment (index into kStrides) of the stride that ends at landing k of the foot.
int segment_of_stride(int k) {
    for (int i = 0, end = 0; i < 4; ++i)
        if (k < (end += kStrides[i])) return i;
    return -1;
}

}  // namespace

TEST_CASE("walk ratio: a level stride s times the nominal takes the nominal stride time over s") {
    const SimOutput o = exact(straight_route(), "foot");
    const std::vector<double>& landing = o.step_times_s;
    REQUIRE(landing.size() == 30);
    int checked = 0;
    for (size_t k = 1; k < landing.size(); ++k) {
        const int seg = segment_of_stride(static_cast<int>(k));
        // From one landing to the next: this stride's swing after the last one's stance, one stride
        // time when both strides belong to the same segment.
        if (seg != segment_of_stride(static_cast<int>(k) - 1)) continue;
        CAPTURE(k);
        CHECK(landing[k] - landing[k - 1] ==
              doctest::Approx(kStrideNominalS / kStrideRatio[seg]).epsilon(1e-9));
        ++checked;
    }
    CHECK(checked == 9 + 8 + 9);
    // The speed grows as s^2: 1.3 m/s at the nominal stride, 1.433 m/s at 1.05, 1.173 m/s at 0.95.
    const double speed_long_mps = 8 * 1.05 * kStrideNominalM / (landing[19] - landing[11]);
    CHECK(speed_long_mps == doctest::Approx(1.3 * 1.05 * 1.05).epsilon(1e-9));
    const double speed_short_mps = 9 * 0.95 * kStrideNominalM / (landing[29] - landing[20]);
    CHECK(speed_short_mps == doctest::Approx(1.3 * 0.95 * 0.95).epsilon(1e-9));
    // The single 20 % longer stride: it swings for 72 % of its time, after a nominal stride's stance.
    const double swing_s = landing[10] - landing[9] - 0.28 * kStrideNominalS;
    CHECK(swing_s == doctest::Approx(0.72 * kStrideNominalS / 1.2).epsilon(1e-9));
}

TEST_CASE("walk ratio: strides on stairs keep the stairs' own period") {
    const Route route = builtin_route("stairs");
    const SimOutput o = exact(route, "foot");
    const std::vector<double>& landing = o.step_times_s;
    // A stride of two stairs on a flight, after another: 2 stairs_step_period_s whatever the stair run.
    int stair_strides = 0;
    for (size_t k = 2; k < landing.size(); ++k) {
        const auto z_at = [&](double t) {
            return o.truth[static_cast<size_t>(std::llround(t * o.rate_hz))].pos_enu_m[2];
        };
        const double rise_m = std::fabs(z_at(landing[k]) - z_at(landing[k - 1]));
        const double rise_before_m = std::fabs(z_at(landing[k - 1]) - z_at(landing[k - 2]));
        if (std::fabs(rise_m - 2.0 * route.stair_rise_m) > 1e-6 || std::fabs(rise_before_m - rise_m) > 1e-6)
            continue;
        CAPTURE(k);
        CHECK(landing[k] - landing[k - 1] == doctest::Approx(2.0 * route.stairs_step_period_s).epsilon(1e-6));
        ++stair_strides;
    }
    CHECK(stair_strides == 16);  // four flights of five strides, the first of each after a level stride
}

TEST_CASE("inverted pendulum: each level step bounces by bounce_m times the rise over the trunk's chord") {
    const SimOutput o = exact(straight_route(), "chest");
    const std::vector<double>& steps = o.step_times_s;  // every landing of either foot
    REQUIRE(steps.size() == 2 * 30);
    const double rise_nominal_m = pendulum_rise_m(0.5 * kStrideNominalM);
    std::vector<double> worst_amplitude_error(4, 0.0), accel_range_mps2(4, 0.0);
    std::vector<int> interior(4, 0);
    double worst_junction_chord_m = 0.0;
    // The bout's first and last steps fade the bounce in and out.
    for (size_t k = 3; k + 3 < steps.size(); ++k) {
        const int seg = segment_of_stride(static_cast<int>(k / 2));  // steps 2j and 2j + 1 end stride j
        const StepBounce b = step_bounce(o, k);
        const double amplitude_m = kChestBounceM * pendulum_rise_m(b.chord_m) / rise_nominal_m;
        CAPTURE(k);
        CAPTURE(seg);
        worst_amplitude_error[seg] =
            std::max(worst_amplitude_error[seg], std::fabs(b.z_max_m - amplitude_m) / amplitude_m);
        // Inside a segment the trunk's chord is the feet's spacing, and the cadence is steady: the range is
        // the oscillation's 2 A (2 pi / T)^2.
        const int first_step =
            2 * (seg == 0 ? 0 : kStrides[0] + (seg > 1 ? kStrides[1] : 0) + (seg > 2 ? kStrides[2] : 0));
        const int last_step = first_step + 2 * kStrides[seg] - 1;
        const double spacing_m = 0.5 * kStrideRatio[seg] * kStrideNominalM;
        if (static_cast<int>(k) >= first_step + 5 && static_cast<int>(k) <= last_step - 5) {
            CHECK(b.chord_m == doctest::Approx(spacing_m).epsilon(1e-6));
            const double step_s = kStrideNominalS / kStrideRatio[seg] / 2.0;
            const double range_mps2 = 2.0 * amplitude_m * std::pow(2.0 * M_PI / step_s, 2.0);
            CHECK(b.accel_range_mps2 == doctest::Approx(range_mps2).epsilon(0.005));
            accel_range_mps2[seg] += b.accel_range_mps2;
            ++interior[seg];
        } else {
            // Where the stride length changes, the smoothed landing moves by a quarter of the change.
            worst_junction_chord_m = std::max(worst_junction_chord_m, std::fabs(b.chord_m - spacing_m));
        }
    }
    std::printf("bounce: the trunk's chord at most %.4f m from the feet's spacing where the stride changes\n",
                worst_junction_chord_m);
    for (int seg = 0; seg < 4; ++seg) {
        if (interior[seg] > 0) accel_range_mps2[seg] /= interior[seg];
        std::printf(
            "bounce, stride ratio %.2f: worst amplitude error %.2e (relative), vertical acceleration range "
            "%.3f m/s^2 (mean of %d steps inside the segment)\n",
            kStrideRatio[seg], worst_amplitude_error[seg], accel_range_mps2[seg], interior[seg]);
        // The amplitude is each step's value at mid-step; beside a longer step it still rises through
        // mid-step, so the highest point lies a little later and higher (by 0.04 % beside the 20 % stride,
        // whose change of length the smoothed landings share with the steps either side; 0.1 % while the
        // bounce followed the feet's spacing).
        CHECK(worst_amplitude_error[seg] < 1e-3);
    }
    CHECK(interior[0] == 10);
    CHECK(interior[2] == 8);
    CHECK(interior[3] == 10);
    // A nominal step keeps bounce_m; a 5 % longer one bounces 10.8 % more at a 5 % higher cadence, so its
    // acceleration range is 22.1 % larger (1.05^4 = 1.216: Weinberg's fourth root reads the 5 %), a 5 %
    // shorter one's 18.1 % smaller (0.95^4 = 0.815).
    CHECK(accel_range_mps2[2] / accel_range_mps2[0] == doctest::Approx(std::pow(1.05, 4)).epsilon(0.01));
    CHECK(accel_range_mps2[3] / accel_range_mps2[0] == doctest::Approx(std::pow(0.95, 4)).epsilon(0.01));
    CHECK(std::pow(accel_range_mps2[2] / accel_range_mps2[0], 0.25) == doctest::Approx(1.05).epsilon(0.002));
}

TEST_CASE("inverted pendulum: a corner step, over which the trunk travels less than the feet, bounces less") {
    // 10 nominal strides east, a 90 deg left turn on the footprint at (14, 0), 10 strides north.
    Route route;
    route.name = "corner";
    route.start_still_s = route.end_still_s = 2.0;
    Waypoint w;
    route.waypoints.push_back(w);
    w.enu_m[0] = 10 * kStrideNominalM;
    route.waypoints.push_back(w);
    w.enu_m[1] = 10 * kStrideNominalM;
    route.waypoints.push_back(w);
    const SimOutput o = exact(route, "chest");
    REQUIRE(o.step_times_s.size() == 40);
    const size_t corner = 19;  // the landing on the corner's footprint: steps 19 and 20 either side of it
    const StepBounce straight = step_bounce(o, 10), before = step_bounce(o, corner),
                     after = step_bounce(o, corner + 1);
    const double spacing_m = 0.5 * kStrideNominalM;
    std::printf(
        "corner: the trunk's chords %.4f and %.4f m over the two steps either side (the feet's %.2f m, "
        "%.1f %% shorter), their bounce %.3f and %.3f cm, %.4f and %.4f of a straight step's %.3f cm\n",
        before.chord_m, after.chord_m, spacing_m, 100.0 * (1.0 - before.chord_m / spacing_m),
        100.0 * before.z_max_m, 100.0 * after.z_max_m, before.z_max_m / straight.z_max_m,
        after.z_max_m / straight.z_max_m, 100.0 * straight.z_max_m);
    CHECK(straight.chord_m == doctest::Approx(spacing_m).epsilon(1e-6));
    // The corner's landing moves a quarter step back along the first leg and a quarter step along the second:
    // the chords are sqrt(0.75^2 + 0.25^2) steps, 21 % shorter than the feet's.
    const double corner_chord_m = spacing_m * std::sqrt(0.75 * 0.75 + 0.25 * 0.25);
    CHECK(before.chord_m == doctest::Approx(corner_chord_m).epsilon(1e-6));
    CHECK(after.chord_m == doctest::Approx(corner_chord_m).epsilon(1e-6));
    // By the pendulum's ratio h(0.553 m) / h(0.7 m) = 0.615: 38 % less (measured 0.617: the amplitude falls
    // into the corner and climbs out of it, so the highest point lies a little off mid-step and higher).
    const double ratio = pendulum_rise_m(corner_chord_m) / pendulum_rise_m(spacing_m);
    CHECK(straight.z_max_m == doctest::Approx(kChestBounceM).epsilon(1e-3));
    CHECK(before.z_max_m / straight.z_max_m == doctest::Approx(ratio).epsilon(5e-3));
    CHECK(after.z_max_m / straight.z_max_m == doctest::Approx(ratio).epsilon(5e-3));
}
