// SPDX-License-Identifier: Apache-2.0
// The inverted pendulum's step length, the pelvis' rise from a vertical
// acceleration, the vertical acceleration at any tilt, and the fit of a
// step-length model linear in its constants.
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include <pednav_pdr/inverted_pendulum.hpp>
#include <pednav_pdr/step_length_model.hpp>
#include <pednav_pdr/vertical_acceleration.hpp>

using namespace pednav::pdr;

TEST_CASE("inverted pendulum: the chord of the arc a rise h makes on a leg of length l") {
    CHECK(inverted_pendulum_step_m(0.9, 0.04) ==
          doctest::Approx(2.0 * std::sqrt(2 * 0.9 * 0.04 - 0.04 * 0.04)));
    CHECK(inverted_pendulum_step_m(0.9, 0.0) == 0.0);
    CHECK(inverted_pendulum_step_m(0.9, -0.01) == 0.0);
    CHECK(inverted_pendulum_step_m(0.9, 2.0) == doctest::Approx(1.8));
}

TEST_CASE("pelvis rise: the range of the twice-integrated vertical acceleration over the step") {
    // z = A cos(2 pi t / T) + a drift the mean removals take out: over one
    // step (one period) the range is 2 A whatever the start phase and an
    // offset of the accelerometer.
    const double A = 0.025, T = 0.55, w = 2 * M_PI / T;
    for (double phase : {0.0, 0.7, 2.0}) {
        std::vector<int64_t> t;
        std::vector<double> a;
        for (int k = 0; k <= 55; ++k) {
            const double ts = k * 0.01;
            t.push_back(static_cast<int64_t>(std::llround(ts * 1e9)));
            a.push_back(-A * w * w * std::cos(w * ts + phase) + 0.3);
        }
        CAPTURE(phase);
        CHECK(pelvis_rise_m(t.data(), a.data(), t.size()) == doctest::Approx(2 * A).epsilon(0.02));
    }
    const int64_t t2[2] = {0, 10000000};
    const double a2[2] = {1.0, -1.0};
    CHECK(pelvis_rise_m(t2, a2, 2) == 0.0);
}

TEST_CASE(
    "vertical acceleration: the specific force along the low-passed gravity, less its norm, at any tilt") {
    VerticalAcceleration v(1.0);
    // Tilted 30 deg about x: gravity along (0, sin 30, cos 30) in the sensor.
    const double g = 9.81, s = std::sin(M_PI / 6), c = std::cos(M_PI / 6);
    double av = 0;
    for (int k = 0; k < 2000; ++k) {
        const double up = 0.5 * std::sin(2 * M_PI * 1.8 * k * 0.01);  // a vertical bounce
        const double f[3] = {0.0, (g + up) * s, (g + up) * c};
        av = v.push(static_cast<int64_t>(k) * 10000000, f);
        if (k > 1500) CHECK(av == doctest::Approx(up).epsilon(0.05).scale(1.0));
    }
    const double w[3] = {0.0, s, c};
    CHECK(v.along_vertical(w) == doctest::Approx(1.0).epsilon(1e-3));
    CHECK(v.dt_s() == doctest::Approx(0.01));
}

TEST_CASE("fit_linear_step_model: the constants of L = c0 g0 + c1 g1 from walks of known length") {
    // Walks whose steps follow L = 1.4 p + 0.05 (p a pendulum step) exactly.
    std::vector<LinearCalibrationWalk> walks;
    for (int w = 0; w < 6; ++w) {
        LinearCalibrationWalk walk{{0.0, 0.0}, 0.0};
        for (int k = 0; k < 14 + w; ++k) {
            const double p = 0.45 + 0.02 * w + 0.01 * std::sin(k);
            walk.basis_sums[0] += p;
            walk.basis_sums[1] += 1.0;
            walk.distance_m += 1.4 * p + 0.05;
        }
        walks.push_back(walk);
    }
    const std::vector<double> c = fit_linear_step_model(walks);
    REQUIRE(c.size() == 2);
    CHECK(c[0] == doctest::Approx(1.4));
    CHECK(c[1] == doctest::Approx(0.05));
    // One constant: the relative least squares of fit_step_length.
    std::vector<LinearCalibrationWalk> one = {{{10.0}, 5.0}, {{10.0}, 6.0}};
    const double x0 = 10.0 / 5.0, x1 = 10.0 / 6.0;  // 1 = c x_w, x_w = G_w / D_w
    CHECK(fit_linear_step_model(one)[0] == doctest::Approx((x0 + x1) / (x0 * x0 + x1 * x1)));
    // Two constants two proportional walks cannot tell apart.
    CHECK_THROWS_AS(fit_linear_step_model({{{1.0, 2.0}, 1.0}, {{2.0, 4.0}, 2.0}}), std::invalid_argument);
    CHECK_THROWS_AS(fit_linear_step_model({}), std::invalid_argument);
    CHECK_THROWS_AS(fit_linear_step_model({{{1.0}, 0.0}}), std::invalid_argument);
}
