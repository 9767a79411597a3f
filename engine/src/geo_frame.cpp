// SPDX-License-Identifier: Apache-2.0
#include "geo_frame.hpp"

#include <cmath>

namespace pednav::engine {

namespace {

constexpr double kA = 6378137.0;               // WGS-84 semi-major axis, m
constexpr double kF = 1.0 / 298.257223563;     // flattening
constexpr double kE2 = kF * (2.0 - kF);        // first eccentricity squared
constexpr double kDeg = 0.017453292519943295;  // rad per degree

struct Ecef {
    double x, y, z;
};

Ecef ecef_of(const pn_geo_point_t& g) {
    const double lat = g.lat_deg * kDeg, lon = g.lon_deg * kDeg;
    const double s = std::sin(lat), c = std::cos(lat);
    const double n = kA / std::sqrt(1.0 - kE2 * s * s);
    return {(n + g.height_m) * c * std::cos(lon), (n + g.height_m) * c * std::sin(lon),
            (n * (1.0 - kE2) + g.height_m) * s};
}

pn_geo_point_t geo_of(const Ecef& e) {
    const double p = std::hypot(e.x, e.y);
    double lat = std::atan2(e.z, p * (1.0 - kE2));
    double h = 0.0;
    for (int i = 0; i < 6; ++i) {  // converges to 1e-12 rad within 3 at walking heights
        const double s = std::sin(lat);
        const double n = kA / std::sqrt(1.0 - kE2 * s * s);
        h = p / std::cos(lat) - n;
        lat = std::atan2(e.z, p * (1.0 - kE2 * n / (n + h)));
    }
    return {lat / kDeg, std::atan2(e.y, e.x) / kDeg, h};
}

}  // namespace

pn_geo_point_t geo_from_enu(const pn_geo_point_t& origin, const double enu[3]) {
    const double lat = origin.lat_deg * kDeg, lon = origin.lon_deg * kDeg;
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    const Ecef o = ecef_of(origin);
    const Ecef p{o.x - so * enu[0] - sl * co * enu[1] + cl * co * enu[2],
                 o.y + co * enu[0] - sl * so * enu[1] + cl * so * enu[2], o.z + cl * enu[1] + sl * enu[2]};
    return geo_of(p);
}

void enu_from_geo(const pn_geo_point_t& origin, const pn_geo_point_t& point, double enu[3]) {
    const double lat = origin.lat_deg * kDeg, lon = origin.lon_deg * kDeg;
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    const Ecef o = ecef_of(origin), p = ecef_of(point);
    const double dx = p.x - o.x, dy = p.y - o.y, dz = p.z - o.z;
    enu[0] = -so * dx + co * dy;
    enu[1] = -sl * co * dx - sl * so * dy + cl * dz;
    enu[2] = cl * co * dx + cl * so * dy + sl * dz;
}

}  // namespace pednav::engine
