#include <pednav_sim/geo.hpp>

#include <cmath>

namespace pednav::sim {

// International standard atmosphere, troposphere.
double standard_pressure_pa(double altitude_m, double sea_level_pa) {
    return sea_level_pa * std::pow(1.0 - 2.25577e-5 * altitude_m, 5.25588);
}

double standard_altitude_m(double pressure_pa, double sea_level_pa) {
    return (1.0 - std::pow(pressure_pa / sea_level_pa, 1.0 / 5.25588)) / 2.25577e-5;
}

}  // namespace pednav::sim
