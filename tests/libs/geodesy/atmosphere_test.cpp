// SPDX-License-Identifier: Apache-2.0
// The standard atmosphere and the barometric formula both ways.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <pednav_geodesy/atmosphere.hpp>

using namespace pednav::geodesy;

TEST_CASE("standard atmosphere pressures against the ISO 2533 table") {
    CHECK(standard_pressure_pa(0.0) == 101325.0);
    CHECK(standard_pressure_pa(1000.0) == doctest::Approx(89874.6).epsilon(2e-5));   // table: 89 874.6 Pa
    CHECK(standard_pressure_pa(5000.0) == doctest::Approx(54019.9).epsilon(1e-4));   // table: 54 019.9 Pa
    CHECK(standard_pressure_pa(11000.0) == doctest::Approx(22632.1).epsilon(1e-5));  // table: 22 632.1 Pa
    // Near the ground the pressure falls by rho g = 1.225 kg/m^3 x 9.80665 m/s^2 = 12.01 Pa per metre:
    // one 3 m storey is 36 Pa.
    CHECK(standard_pressure_pa(0.0) - standard_pressure_pa(3.0) == doctest::Approx(36.03).epsilon(1e-3));
    // Against a reference level other than the standard sea level.
    CHECK(standard_pressure_pa(1000.0, 95000.0) ==
          doctest::Approx(95000.0 * 89874.6 / 101325.0).epsilon(2e-5));
}

TEST_CASE("pressure altitude is the inverse of the standard pressure, at any reference") {
    double worst_m = 0;
    for (double reference_pa : {101325.0, 95000.0, 102500.0})
        for (double h = -400.0; h <= 9000.0; h += 37.5)
            worst_m = std::max(
                worst_m,
                std::abs(pressure_altitude_m(standard_pressure_pa(h, reference_pa), reference_pa) - h));
    CHECK(worst_m < 1e-8);
    CHECK(pressure_altitude_m(101325.0) == 0.0);
    CHECK(pressure_altitude_m(89874.6) == doctest::Approx(1000.0).epsilon(2e-4));
    // A barometer's climb from the pressure at the start: 12.01 Pa less is one metre up, 12 Pa more
    // one metre down.
    CHECK(pressure_altitude_m(101325.0 - 12.0132, 101325.0) == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(pressure_altitude_m(101337.0, 101325.0) == doctest::Approx(-0.9989).epsilon(1e-3));
}
