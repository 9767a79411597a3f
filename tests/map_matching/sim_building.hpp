// SPDX-License-Identifier: Apache-2.0
// The map of a simulated route's building, as a map matcher needs it: the
// route's walls per floor with a door wherever the route walks through one
// (the simulator draws walls without openings), a stairs area over each
// flight between two floors, and an altitude-update zone around it on both. Written as a pednav.map/1 document in local
// metres for the engine.
#pragma once

#include <string>

#include <pednav_indoor_map/map.hpp>
#include <pednav_sim/route.hpp>

namespace pednav::test {

struct SimBuildingOptions {
    double door_width_m = 1.2;     // opening cut around each place the route passes a wall
    double stairs_margin_m = 0.75; // stairs area: the flights' waypoints, widened by this
    double altitude_zone_margin_m = 3.0;  // altitude-update zones: the flights' waypoints widened by this, on both floors
};

indoor_map::Map sim_building_map(const sim::Route& route, const SimBuildingOptions& options = {});

// The map as a pednav.map/1 FeatureCollection in "local-enu" metres.
std::string map_to_geojson(const indoor_map::Map& map);

}  // namespace pednav::test
