// Local East-North-Up <-> WGS-84 conversions about an origin (tangent-plane
// approximation with the ellipsoid's radii of curvature: millimetres over a
// few hundred metres, plenty for a building).
#pragma once

namespace pednav::sim {

struct GeoOrigin {
    double lat_deg = 0.0;
    double lon_deg = 0.0;
    double height_m = 0.0;
};

void enu_to_llh(const GeoOrigin& origin, const double enu_m[3], double& lat_deg, double& lon_deg,
                double& height_m);
void llh_to_enu(const GeoOrigin& origin, double lat_deg, double lon_deg, double height_m, double enu_m[3]);

// Pressure of the standard atmosphere at an altitude, and its inverse.
double standard_pressure_pa(double altitude_m, double sea_level_pa = 101325.0);
double standard_altitude_m(double pressure_pa, double sea_level_pa = 101325.0);

}  // namespace pednav::sim
