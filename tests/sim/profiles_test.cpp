// SPDX-License-Identifier: Apache-2.0
// The analytic derivatives of every profile against central differences.
#include <doctest/doctest.h>

#include <cmath>

#include "profiles.hpp"
#include "spline.hpp"

using namespace pednav::sim::detail;

namespace {

template <typename F>
void check_derivatives(F f, double lo, double hi) {
    const double h = 1e-5;
    for (int i = 1; i < 200; ++i) {
        const double x = lo + (hi - lo) * i / 200.0;
        const Profile p = f(x), pm = f(x - h), pp = f(x + h);
        CAPTURE(x);
        CHECK(p.df == doctest::Approx((pp.f - pm.f) / (2 * h)).epsilon(1e-5).scale(1.0));
        CHECK(p.ddf == doctest::Approx((pp.df - pm.df) / (2 * h)).epsilon(1e-5).scale(1.0));
    }
}

}  // namespace

TEST_CASE("transition: 0 to 1 with exact derivatives, rest at both ends") {
    check_derivatives(transition, -0.2, 1.2);
    CHECK(transition(0.5).f == doctest::Approx(0.5));
    // The polynomial itself comes to rest at both ends (u = 0 and 1 are
    // clamped branches, so probe just inside): value, rate and acceleration
    // vanish like u^4, u^3 and u^2.
    for (double e : {1e-3, 1e-4}) {
        const Profile a = transition(e), b = transition(1.0 - e);
        CHECK(std::abs(a.f) < 40 * std::pow(e, 4));
        CHECK(std::abs(a.df) < 150 * std::pow(e, 3));
        CHECK(std::abs(a.ddf) < 450 * e * e);
        CHECK(std::abs(1.0 - b.f) < 40 * std::pow(e, 4));
        CHECK(std::abs(b.df) < 150 * std::pow(e, 3));
        CHECK(std::abs(b.ddf) < 450 * e * e);
    }
    CHECK(transition(0.5).df == doctest::Approx(35.0 / 16.0));
}

TEST_CASE("bump: peak 1 at the middle with exact derivatives") {
    check_derivatives(bump, -0.2, 1.2);
    CHECK(bump(0.5).f == doctest::Approx(1.0));
    CHECK(bump(0.5).df == doctest::Approx(0.0));
    CHECK(bump(0.25).f == doctest::Approx(256.0 * std::pow(0.25 * 0.75, 4)));
}

TEST_CASE("clamped spline: through the knots, zero end slopes, exact derivatives") {
    const ClampedSpline s({0.0, 0.4, 1.0, 1.3, 2.0}, {0.0, 0.5, 1.5, 1.6, 3.0});
    CHECK(s.at(0.4).f == doctest::Approx(0.5));
    CHECK(s.at(1.3).f == doctest::Approx(1.6));
    CHECK(s.at(1e-9).df == doctest::Approx(0.0).epsilon(1e-6));
    CHECK(s.at(2.0 - 1e-9).df == doctest::Approx(0.0).epsilon(1e-6));
    check_derivatives([&](double t) { return s.at(t); }, 0.0123, 1.9811);  // grid misses the knots
}
