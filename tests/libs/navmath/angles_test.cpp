// SPDX-License-Identifier: Apache-2.0
// atan2_fast against libm, wrap_pi.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <pednav_navmath/angles.hpp>

using namespace pednav::navmath;

TEST_CASE("atan2_fast agrees with libm's atan2 to about an ulp in every octant") {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double max_err = 0.0;
    for (int i = 0; i < 200000; ++i) {
        double y = u(rng), x = u(rng);
        if (i % 3 == 0) y *= 1e-4;
        if (i % 5 == 0) x *= 1e-7;
        max_err = std::max(max_err, std::abs(atan2_fast(y, x) - std::atan2(y, x)));
    }
    CHECK(max_err < 1e-15);
    for (double y : {0.0, -0.0, 1.0, -1.0})
        for (double x : {0.0, -0.0, 1.0, -1.0}) CHECK(atan2_fast(y, x) == std::atan2(y, x));
    CHECK(atan2_fast(1.0, 1.0) == std::atan2(1.0, 1.0));
    CHECK(std::isnan(atan2_fast(NAN, 1.0)));
}

TEST_CASE("wrap_pi brings any angle into [-pi, pi)") {
    CHECK(wrap_pi(0.0) == 0.0);
    CHECK(wrap_pi(M_PI) == -M_PI);  // the upper end maps to the lower
    CHECK(wrap_pi(-M_PI) == -M_PI);
    CHECK(wrap_pi(1.5 * M_PI) == doctest::Approx(-0.5 * M_PI).epsilon(1e-15));
    CHECK(wrap_pi(-1.5 * M_PI) == doctest::Approx(0.5 * M_PI).epsilon(1e-15));
    CHECK(wrap_pi(7.0) == doctest::Approx(7.0 - 2.0 * M_PI).epsilon(1e-15));
    CHECK(wrap_pi(-7.0) == doctest::Approx(-7.0 + 2.0 * M_PI).epsilon(1e-15));
    CHECK(wrap_pi(100.0 * M_PI + 0.25) == doctest::Approx(0.25).epsilon(1e-12));
}
