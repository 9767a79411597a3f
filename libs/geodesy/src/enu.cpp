// WGS-84 local tangent plane: radii of curvature at the origin latitude.
#include <cmath>

#include "pednav_geodesy/enu.hpp"

namespace pednav::geodesy {

namespace {

constexpr double kA = 6378137.0;               // WGS-84 semi-major axis, m
constexpr double kE2 = 6.69437999014e-3;       // first eccentricity squared
constexpr double kDeg = 0.017453292519943295;  // rad per degree

void radii(double lat_deg, double* meridian_m, double* normal_m) {
    const double s = std::sin(lat_deg * kDeg);
    const double w = std::sqrt(1.0 - kE2 * s * s);
    *normal_m = kA / w;
    *meridian_m = kA * (1.0 - kE2) / (w * w * w);
}

}  // namespace

void geodetic_to_enu(const GeodeticPoint& origin, double lat_deg, double lon_deg, double height_m, double enu_m[3]) {
    double m = 0.0, n = 0.0;
    radii(origin.lat_deg, &m, &n);
    double dlon = lon_deg - origin.lon_deg;
    if (dlon > 180.0) dlon -= 360.0;
    if (dlon < -180.0) dlon += 360.0;
    enu_m[0] = dlon * kDeg * (n + origin.height_m) * std::cos(origin.lat_deg * kDeg);
    enu_m[1] = (lat_deg - origin.lat_deg) * kDeg * (m + origin.height_m);
    enu_m[2] = height_m - origin.height_m;
}

void enu_to_geodetic(const GeodeticPoint& origin, const double enu_m[3], double* lat_deg, double* lon_deg,
                     double* height_m) {
    double m = 0.0, n = 0.0;
    radii(origin.lat_deg, &m, &n);
    *lat_deg = origin.lat_deg + enu_m[1] / (m + origin.height_m) / kDeg;
    *lon_deg = origin.lon_deg + enu_m[0] / ((n + origin.height_m) * std::cos(origin.lat_deg * kDeg)) / kDeg;
    if (*lon_deg > 180.0) *lon_deg -= 360.0;
    if (*lon_deg < -180.0) *lon_deg += 360.0;
    *height_m = origin.height_m + enu_m[2];
}

}  // namespace pednav::geodesy
