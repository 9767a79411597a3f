// SPDX-License-Identifier: Apache-2.0
// WGS-84 <-> ENU through earth-centred, earth-fixed (ECEF) coordinates:
//   ECEF of (lat, lon, h): N = a / sqrt(1 - e^2 sin^2 lat),
//     x = (N + h) cos lat cos lon, y = (N + h) cos lat sin lon, z = (N (1 - e^2) + h) sin lat;
//   ENU = R(lat0, lon0) (ECEF - ECEF0) with the rows of R the east, north and up
//   unit vectors at the origin; the inverse by R^T and Bowring's iteration for
//   latitude and height (converges to 1e-12 rad within three steps near the
//   surface; six are taken).
#include <cmath>

#include "pednav_geodesy/enu.hpp"

namespace pednav::geodesy {

namespace {

constexpr double kA = 6378137.0;               // WGS-84 semi-major axis, m
constexpr double kF = 1.0 / 298.257223563;     // WGS-84 flattening
constexpr double kE2 = kF * (2.0 - kF);        // first eccentricity squared
constexpr double kDeg = 0.017453292519943295;  // rad per degree

struct Ecef {
    double x, y, z;
};

Ecef ecef_of(double lat_deg, double lon_deg, double height_m) {
    const double lat = lat_deg * kDeg, lon = lon_deg * kDeg;
    const double s = std::sin(lat), c = std::cos(lat);
    const double n = kA / std::sqrt(1.0 - kE2 * s * s);
    return {(n + height_m) * c * std::cos(lon), (n + height_m) * c * std::sin(lon), (n * (1.0 - kE2) + height_m) * s};
}

// East, north and up unit vectors at the origin, as the rows of R.
struct Frame {
    double e[3], n[3], u[3];
};

Frame frame_at(const GeodeticPoint& o) {
    const double sl = std::sin(o.lat_deg * kDeg), cl = std::cos(o.lat_deg * kDeg);
    const double so = std::sin(o.lon_deg * kDeg), co = std::cos(o.lon_deg * kDeg);
    return {{-so, co, 0.0}, {-sl * co, -sl * so, cl}, {cl * co, cl * so, sl}};
}

}  // namespace

void geodetic_to_enu(const GeodeticPoint& origin, double lat_deg, double lon_deg, double height_m, double enu_m[3]) {
    const Ecef o = ecef_of(origin.lat_deg, origin.lon_deg, origin.height_m);
    const Ecef p = ecef_of(lat_deg, lon_deg, height_m);
    const double d[3] = {p.x - o.x, p.y - o.y, p.z - o.z};
    const Frame f = frame_at(origin);
    enu_m[0] = f.e[0] * d[0] + f.e[1] * d[1] + f.e[2] * d[2];
    enu_m[1] = f.n[0] * d[0] + f.n[1] * d[1] + f.n[2] * d[2];
    enu_m[2] = f.u[0] * d[0] + f.u[1] * d[1] + f.u[2] * d[2];
}

void enu_to_geodetic(const GeodeticPoint& origin, const double enu_m[3], double* lat_deg, double* lon_deg,
                     double* height_m) {
    const Ecef o = ecef_of(origin.lat_deg, origin.lon_deg, origin.height_m);
    const Frame f = frame_at(origin);
    const double x = o.x + f.e[0] * enu_m[0] + f.n[0] * enu_m[1] + f.u[0] * enu_m[2];
    const double y = o.y + f.e[1] * enu_m[0] + f.n[1] * enu_m[1] + f.u[1] * enu_m[2];
    const double z = o.z + f.e[2] * enu_m[0] + f.n[2] * enu_m[1] + f.u[2] * enu_m[2];
    const double p = std::hypot(x, y);
    double lat = std::atan2(z, p * (1.0 - kE2));
    double h = 0.0;
    for (int i = 0; i < 6; ++i) {
        const double s = std::sin(lat);
        const double n = kA / std::sqrt(1.0 - kE2 * s * s);
        h = p / std::cos(lat) - n;
        lat = std::atan2(z, p * (1.0 - kE2 * n / (n + h)));
    }
    *lat_deg = lat / kDeg;
    *lon_deg = std::atan2(y, x) / kDeg;
    *height_m = h;
}

}  // namespace pednav::geodesy
