#include <pednav_sim/geo.hpp>

#include <cmath>

namespace pednav::sim {

// International standard atmosphere, troposphere.
double standard_pressure_pa(double altitude_m, double sea_level_pa) {
    return sea_level_pa * std::pow(1.0 - 2.25577e-5 * altitude_m, 5.25588);
}

}  // namespace pednav::sim
