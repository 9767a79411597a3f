// SPDX-License-Identifier: Apache-2.0
// The simulated gait keeps the walk ratio and the trunk bounces as an
// inverted pendulum (docs/simulator.md, "Kinematics"): a level stride s times
// the nominal takes the nominal stride time over s, stairs keep their period;
// each level step's bounce is bounce_m times the pendulum's rise over that
// step against the nominal step's, so the vertical acceleration range of a
// step grows as its length to the fourth power (what Weinberg's model reads).
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

TEST_CASE("inverted pendulum: each level step bounces by bounce_m times its rise over the nominal step's") {
    const SimOutput o = exact(straight_route(), "chest");
    const std::vector<double>& steps = o.step_times_s;  // every landing of either foot
    REQUIRE(steps.size() == 2 * 30);
    const double rise_nominal_m = pendulum_rise_m(0.5 * kStrideNominalM);
    std::vector<double> worst_amplitude_error(4, 0.0), accel_range_mps2(4, 0.0);
    std::vector<int> interior(4, 0);
    for (size_t k = 1; k + 1 < steps.size(); ++k) {
        const int seg = segment_of_stride(static_cast<int>(k / 2));  // steps 2j and 2j + 1 end stride j
        const double step_m = 0.5 * kStrideRatio[seg] * kStrideNominalM;
        const double amplitude_m = kChestBounceM * pendulum_rise_m(step_m) / rise_nominal_m;
        // Over step k (from landing k - 1 to landing k): the highest point, at mid-step, and the
        // vertical acceleration's range.
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
        CAPTURE(k);
        CAPTURE(seg);
        if (k >= 3 && k + 3 < steps.size())  // the bout's first and last steps fade the bounce in and out
            worst_amplitude_error[seg] =
                std::max(worst_amplitude_error[seg], std::fabs(z_max - amplitude_m) / amplitude_m);
        // Inside a segment the cadence is steady: the range is the oscillation's 2 A (2 pi / T)^2.
        const int first_step =
            2 * (seg == 0 ? 0 : kStrides[0] + (seg > 1 ? kStrides[1] : 0) + (seg > 2 ? kStrides[2] : 0));
        const int last_step = first_step + 2 * kStrides[seg] - 1;
        if (static_cast<int>(k) >= first_step + 5 && static_cast<int>(k) <= last_step - 5) {
            const double step_s = kStrideNominalS / kStrideRatio[seg] / 2.0;
            const double range_mps2 = 2.0 * amplitude_m * std::pow(2.0 * M_PI / step_s, 2.0);
            CHECK((a_max - a_min) == doctest::Approx(range_mps2).epsilon(0.005));
            accel_range_mps2[seg] += a_max - a_min;
            ++interior[seg];
        }
    }
    for (int seg = 0; seg < 4; ++seg) {
        if (interior[seg] > 0) accel_range_mps2[seg] /= interior[seg];
        std::printf(
            "bounce, stride ratio %.2f: worst amplitude error %.2e (relative), vertical acceleration range "
            "%.3f m/s^2 (mean of %d steps inside the segment)\n",
            kStrideRatio[seg], worst_amplitude_error[seg], accel_range_mps2[seg], interior[seg]);
        // The amplitude is each step's value at mid-step; beside a longer step it still rises through
        // mid-step, so the highest point lies a little later and higher (by 0.1 % beside the 20 % stride).
        CHECK(worst_amplitude_error[seg] < 2e-3);
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
