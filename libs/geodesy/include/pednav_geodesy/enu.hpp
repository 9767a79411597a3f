// SPDX-License-Identifier: Apache-2.0
// WGS-84 latitude, longitude and height <-> local East-North-Up metres in the
// tangent plane at an origin. Exact (through earth-centred coordinates): up is
// the ellipsoid normal at the origin, so a point far away lies below the plane
// by its curvature (about 7.8 cm at 1 km), as a GNSS fix there would.
#pragma once

namespace pednav::geodesy {

// A point on or above the WGS-84 ellipsoid: degrees north and east, metres
// above the ellipsoid.
struct GeodeticPoint {
    double lat_deg = 0.0, lon_deg = 0.0, height_m = 0.0;
};

// Latitude/longitude/height to east/north/up metres from `origin`.
void geodetic_to_enu(const GeodeticPoint& origin, double lat_deg, double lon_deg, double height_m,
                     double enu_m[3]);
// The inverse of geodetic_to_enu.
void enu_to_geodetic(const GeodeticPoint& origin, const double enu_m[3], double* lat_deg, double* lon_deg,
                     double* height_m);

}  // namespace pednav::geodesy
