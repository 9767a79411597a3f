// SPDX-License-Identifier: Apache-2.0
// The engine's ENU frame around its geodetic origin: exact WGS-84 conversions
// between a geodetic point and ENU metres of the origin's tangent plane.
#pragma once

#include <pednav/pn_types.h>

namespace pednav::engine {

pn_geo_point_t geo_from_enu(const pn_geo_point_t& origin, const double pos_enu_m[3]);
void enu_from_geo(const pn_geo_point_t& origin, const pn_geo_point_t& point, double pos_enu_m[3]);

}  // namespace pednav::engine
