// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <pednav_pdr/step_vector.hpp>
#include <pednav_pdr/walking_heading.hpp>

using namespace pednav::pdr;

namespace {
std::vector<HorizontalSample> samples(double rate_hz, double seconds, double (*east)(double), double (*north)(double)) {
    std::vector<HorizontalSample> s;
    for (int k = 0; k <= static_cast<int>(seconds * rate_hz); ++k) {
        const double t = k / rate_hz;
        s.push_back({static_cast<int64_t>(std::llround(t * 1e9)), east(t), north(t)});
    }
    return s;
}
}  // namespace

TEST_CASE("step vector: the double integral with v = 0 at the step's start") {
    // Constant acceleration: 1/2 a T^2 (trapezoids are exact for it).
    auto s = samples(100.0, 0.5, [](double) { return 2.0; }, [](double) { return -1.0; });
    PlaneVector d = double_integral(s.data(), s.size(), false);
    CHECK(d.east_m == doctest::Approx(0.25));
    CHECK(d.north_m == doctest::Approx(-0.125));
    // remove_mean takes a constant (a tilt's gravity leak) out entirely.
    d = double_integral(s.data(), s.size(), true);
    CHECK(std::fabs(d.east_m) < 1e-12);
    // A trunk that decelerates after the heel strike: v = v0 cos(w t) about the mean speed over one
    // period T gives -v0 T with v taken as 0 at the start: it points backwards (eq. 1, K < 0).
    auto surge = samples(400.0, 0.55, [](double t) { return -0.25 * (2 * M_PI / 0.55) * std::sin(2 * M_PI * t / 0.55); },
                         [](double) { return 0.0; });
    d = double_integral(surge.data(), surge.size(), false);
    CHECK(d.east_m == doctest::Approx(-0.25 * 0.55).epsilon(1e-3));
    CHECK(double_integral(s.data(), 1, false).east_m == 0.0);
}

TEST_CASE("step vector buffer: a step's samples, the last one shared with the next, a time span") {
    StepVectorBuffer b(1.0);
    for (int k = 0; k <= 300; ++k) b.add({static_cast<int64_t>(k) * 10000000, 1.0, 0.0});  // 3 s at 100 Hz
    CHECK(b.size() <= 102);  // the last second
    // [2.5, 3.0] s: 0.5 s of 1 m/s^2 -> 0.125 m.
    PlaneVector d = b.close(2500000000, 3000000000, false);
    CHECK(d.east_m == doctest::Approx(0.125));
    CHECK(b.size() == 1);
    d = b.close(3000000000, 3500000000, false);
    CHECK(d.east_m == 0.0);
}

TEST_CASE("walking heading: a body axis's level heading, clockwise from north") {
    // Turned 90 deg counter-clockwise about up: body x points north.
    const double q[4] = {std::cos(M_PI / 4), 0, 0, std::sin(M_PI / 4)};
    CHECK(axis_heading_rad(q, parse_body_axis("x")) == doctest::Approx(0.0));
    CHECK(axis_heading_rad(q, parse_body_axis("y")) == doctest::Approx(-M_PI / 2));  // left = west
    CHECK(std::fabs(axis_heading_rad(q, parse_body_axis("-x"))) == doctest::Approx(M_PI));
    CHECK(std::isnan(axis_heading_rad(q, parse_body_axis("z"))));
    const double identity[4] = {1, 0, 0, 0};
    CHECK(axis_heading_rad(identity, parse_body_axis("x")) == doctest::Approx(M_PI / 2));  // east
    CHECK_THROWS(parse_body_axis("w"));
}
