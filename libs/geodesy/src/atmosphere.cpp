// SPDX-License-Identifier: Apache-2.0
#include "pednav_geodesy/atmosphere.hpp"

#include <cmath>

namespace pednav::geodesy {

namespace {
constexpr double kLapseOverT0_per_m = 2.25577e-5;  // L / T0
constexpr double kExponent = 5.25588;             // g M / (R L)
}  // namespace

double standard_pressure_pa(double altitude_m, double reference_pa) {
    return reference_pa * std::pow(1.0 - kLapseOverT0_per_m * altitude_m, kExponent);
}

double pressure_altitude_m(double pressure_pa, double reference_pa) {
    return (1.0 - std::pow(pressure_pa / reference_pa, 1.0 / kExponent)) / kLapseOverT0_per_m;
}

}  // namespace pednav::geodesy
