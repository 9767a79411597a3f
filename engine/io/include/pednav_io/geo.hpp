// WGS-84 <-> local East-North-Up metres around an origin, for ground-truth
// points read from files (IPIN POSI) and for the GeoJSON/GPX writers.
// Local tangent plane: exact enough for the few kilometres of a walk.
#pragma once

#include <cstdint>

namespace pednav::io {

struct Origin {
    double lat_deg = 0.0, lon_deg = 0.0, height_m = 0.0;
    bool known = false;
    int64_t utc_ns_at_zero = 0;  // UTC (ns since 1970) of t_ns = 0 when known, else 0; GPX writes <time> then
};

// Latitude/longitude/height to east/north/up metres from `origin`.
void geodetic_to_enu(const Origin& origin, double lat_deg, double lon_deg, double height_m, double enu_m[3]);
// The inverse of geodetic_to_enu.
void enu_to_geodetic(const Origin& origin, const double enu_m[3], double* lat_deg, double* lon_deg,
                     double* height_m);

}  // namespace pednav::io
