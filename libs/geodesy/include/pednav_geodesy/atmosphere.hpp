// SPDX-License-Identifier: Apache-2.0
// The International Standard Atmosphere's troposphere (ISO 2533, below
// 11 km): pressure at an altitude, and the barometric formula the other way,
// the altitude of a pressure above a reference level. The simulated
// barometer uses the first; a barometer's height change uses the second with
// the pressure at the start as the reference.
//
//   p(h) = p_ref (1 - L h / T0)^(g M / (R L)),  L / T0 = 2.25577e-5 /m,
//   g M / (R L) = 5.25588
// (lapse rate L = 6.5 K/km, T0 = 288.15 K at the reference level). Heights
// are those of the standard temperature profile: a reference level warmer or
// colder than 15 C scales them by T / 288.15 (0.35 % per kelvin).
#pragma once

namespace pednav::geodesy {

// Pressure of the standard atmosphere at altitude_m above the level where it
// is reference_pa (by default the standard sea level).
double standard_pressure_pa(double altitude_m, double reference_pa = 101325.0);

// The altitude, in metres above the level where the pressure is
// reference_pa, at which the standard atmosphere has pressure_pa: the inverse
// of standard_pressure_pa. Both pressures positive.
double pressure_altitude_m(double pressure_pa, double reference_pa = 101325.0);

}  // namespace pednav::geodesy
