// SPDX-License-Identifier: Apache-2.0
// A route's building as a pednav.map/1 document (docs/maps.md), the
// building.geojson of a simulated walk: its walls, with a doorway wherever the
// route passes through one, its flights of stairs as `stairs` arrows between
// the floors they join, altitude zones along its level stretches (when it has
// more than one floor), the start as a landmark, and the path as a GIS extra.
#pragma once

#include <nlohmann/json.hpp>

#include "route.hpp"

namespace pednav::sim {

// Width of the doorway cut into a wall where the route crosses it, m.
constexpr double kDoorWidthM = 1.0;

// WGS-84 (lon, lat) around the route's origin, with "pednav:origin" and
// "pednav:floor_height_m".
nlohmann::json building_map(const Route& route);

}  // namespace pednav::sim
