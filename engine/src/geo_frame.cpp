// SPDX-License-Identifier: Apache-2.0
#include "geo_frame.hpp"

#include <pednav_geodesy/enu.hpp>

namespace pednav::engine {

namespace {
geodesy::GeodeticPoint point_of(const pn_geo_point_t& p) { return {p.lat_deg, p.lon_deg, p.height_m}; }
}  // namespace

pn_geo_point_t geo_from_enu(const pn_geo_point_t& origin, const double pos_enu_m[3]) {
    pn_geo_point_t g{0.0, 0.0, 0.0};
    geodesy::enu_to_geodetic(point_of(origin), pos_enu_m, &g.lat_deg, &g.lon_deg, &g.height_m);
    return g;
}

void enu_from_geo(const pn_geo_point_t& origin, const pn_geo_point_t& point, double pos_enu_m[3]) {
    geodesy::geodetic_to_enu(point_of(origin), point.lat_deg, point.lon_deg, point.height_m, pos_enu_m);
}

}  // namespace pednav::engine
