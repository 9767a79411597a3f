#include <pednav_sim/geo.hpp>

#include <cmath>

namespace pednav::sim {

namespace {

constexpr double kA = 6378137.0;          // WGS-84 semi-major axis
constexpr double kE2 = 6.69437999014e-3;  // first eccentricity squared
constexpr double kDeg = M_PI / 180.0;

// Meridian (north) and prime-vertical (east) radii of curvature.
void radii(double lat_rad, double& r_north, double& r_east) {
    const double s = std::sin(lat_rad);
    const double w = std::sqrt(1.0 - kE2 * s * s);
    r_east = kA / w;
    r_north = kA * (1.0 - kE2) / (w * w * w);
}

}  // namespace

void enu_to_llh(const GeoOrigin& o, const double enu_m[3], double& lat_deg, double& lon_deg,
                double& height_m) {
    double rn = 0.0, re = 0.0;
    radii(o.lat_deg * kDeg, rn, re);
    lat_deg = o.lat_deg + enu_m[1] / (rn + o.height_m) / kDeg;
    lon_deg = o.lon_deg + enu_m[0] / ((re + o.height_m) * std::cos(o.lat_deg * kDeg)) / kDeg;
    height_m = o.height_m + enu_m[2];
}

void llh_to_enu(const GeoOrigin& o, double lat_deg, double lon_deg, double height_m, double enu_m[3]) {
    double rn = 0.0, re = 0.0;
    radii(o.lat_deg * kDeg, rn, re);
    enu_m[0] = (lon_deg - o.lon_deg) * kDeg * (re + o.height_m) * std::cos(o.lat_deg * kDeg);
    enu_m[1] = (lat_deg - o.lat_deg) * kDeg * (rn + o.height_m);
    enu_m[2] = height_m - o.height_m;
}

// International standard atmosphere, troposphere.
double standard_pressure_pa(double altitude_m, double sea_level_pa) {
    return sea_level_pa * std::pow(1.0 - 2.25577e-5 * altitude_m, 5.25588);
}

double standard_altitude_m(double pressure_pa, double sea_level_pa) {
    return (1.0 - std::pow(pressure_pa / sea_level_pa, 1.0 / 5.25588)) / 2.25577e-5;
}

}  // namespace pednav::sim
