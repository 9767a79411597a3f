// The standard atmosphere, for the simulated barometer. (WGS-84 <-> local ENU
// conversions are pednav_io's, pednav_io/geo.hpp.)
#pragma once

namespace pednav::sim {

// Pressure of the standard atmosphere at an altitude.
double standard_pressure_pa(double altitude_m, double sea_level_pa = 101325.0);

}  // namespace pednav::sim
