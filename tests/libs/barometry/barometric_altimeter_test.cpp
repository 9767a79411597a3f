// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_geodesy/atmosphere.hpp>

using namespace pednav::barometry;
using pednav::geodesy::standard_pressure_pa;

namespace {

BarometricAltimeterConfig config() {
    BarometricAltimeterConfig c;
    c.reference_s = 5.0;
    c.smoothing_s = 0.5;
    c.rate_smoothing_s = 1.0;
    c.floor_height_m = 3.5;
    c.floor_hysteresis_m = 0.5;
    c.max_gap_s = 5.0;
    return c;
}

int64_t ns(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

}  // namespace

TEST_CASE("altimeter: the barometric formula above a learnt reference, not a fixed m/Pa") {
    // A building 900 m up: the start pressure is not sea level's.
    const double start_pa = standard_pressure_pa(900.0);
    BarometricAltimeter alt(config());
    double t = 0;
    for (int i = 0; i < 50; ++i, t += 0.1) alt.push(ns(t), start_pa);
    CHECK(!alt.ready());
    alt.push(ns(t), start_pa);
    REQUIRE(alt.ready());
    CHECK(alt.reference_pa() == doctest::Approx(start_pa));
    // Climb 35 m (ten floors) at 0.5 m/s, then hold.
    for (double h = 0; h < 35.0; h += 0.05, t += 0.1) alt.push(ns(t), standard_pressure_pa(900.0 + h));
    for (int i = 0; i < 100; ++i, t += 0.1) alt.push(ns(t), standard_pressure_pa(935.0));
    CHECK(alt.altitude_m() == doctest::Approx(35.0).epsilon(1e-3));
    CHECK(alt.floor() == 10);
    // 35 m of pressure difference read with -0.083 m/Pa, the sea-level factor, is about 10 % short here.
    const double fixed_factor_m = 0.083 * (start_pa - standard_pressure_pa(935.0));
    CHECK(fixed_factor_m < 0.92 * 35.0);
}

TEST_CASE("altimeter: vertical rate, floor hysteresis, re-anchoring, gaps") {
    BarometricAltimeter alt(config());
    const double p0 = 101000.0;
    double t = 0;
    for (int i = 0; i <= 50; ++i, t += 0.1) alt.push(ns(t), p0);
    REQUIRE(alt.ready());
    // Up at 0.4 m/s for 5 s: the rate follows.
    double h = 0;
    for (int i = 0; i < 50; ++i, t += 0.1, h += 0.04) alt.push(ns(t), standard_pressure_pa(h, p0));
    CHECK(alt.vertical_rate_mps() == doctest::Approx(0.4).epsilon(0.05));
    // 2.1 m is past half a floor (1.75 m) but not past the hysteresis (2.25 m): still floor 0.
    for (int i = 0; i < 60; ++i, t += 0.1) alt.push(ns(t), standard_pressure_pa(2.1, p0));
    CHECK(alt.floor() == 0);
    CHECK(std::fabs(alt.vertical_rate_mps()) < 0.01);
    for (int i = 0; i < 60; ++i, t += 0.1) alt.push(ns(t), standard_pressure_pa(3.4, p0));
    CHECK(alt.floor() == 1);
    // Weather: the pressure falls 40 Pa (3.3 m) while the walker stays; a zone of known height re-anchors.
    for (int i = 0; i < 60; ++i, t += 0.1) alt.push(ns(t), standard_pressure_pa(3.4, p0) - 40.0);
    CHECK(alt.altitude_m() > 6.0);
    alt.set_altitude(3.5, 1);
    CHECK(alt.altitude_m() == doctest::Approx(3.5));
    CHECK(alt.floor() == 1);
    // A gap restarts the filter at the next reading instead of smoothing across it.
    t += 30.0;
    alt.push(ns(t), standard_pressure_pa(3.4, p0) - 40.0 - 12.0);
    CHECK(alt.altitude_m() == doctest::Approx(3.5 + 1.0).epsilon(0.03));
    // Bad readings are counted and change nothing.
    const double before = alt.altitude_m();
    alt.push(ns(t + 0.1), -5.0);
    alt.push(ns(t + 0.2), NAN);
    alt.push(ns(t - 1.0), p0);
    CHECK(alt.rejected() == 3);
    CHECK(alt.altitude_m() == before);
    alt.reset();
    CHECK(!alt.ready());
    CHECK(alt.rejected() == 0);
}

TEST_CASE("altimeter: a config out of range is refused") {
    BarometricAltimeterConfig c = config();
    c.floor_hysteresis_m = 2.0;  // beyond half a floor
    CHECK_THROWS_AS(BarometricAltimeter{c}, std::invalid_argument);
    c = config();
    c.reference_s = 0;
    CHECK_THROWS_AS(BarometricAltimeter{c}, std::invalid_argument);
}
