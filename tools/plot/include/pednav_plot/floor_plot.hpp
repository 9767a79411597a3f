// SPDX-License-Identifier: Apache-2.0
// A walk over a building map, one panel per floor: the floor's walls,
// no-particle zones, stairs/escalator/lift arrows and landmarks, and the part
// of each series (truth, track) on that floor.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <pednav_indoor_map/map.hpp>
#include <pednav_plot/walk_plot.hpp>

namespace pednav::plot {

// A series with the floor of each of its points (empty: all on floor 0).
struct FloorSeries {
    Series series;
    std::vector<int> floors;
};

// One panel per floor the map or a series is on, ascending, titled
// "floor N". `landmark_names` (by landmark index, may be shorter) label the
// map's landmarks.
std::vector<MapPanel> floor_panels(const indoor_map::Map& map, const std::vector<std::string>& landmark_names,
                                   const std::vector<FloorSeries>& series);

// The names of a pednav.map/1 document's landmarks ("name" or "pednav:name"
// of each landmark feature, in the order read_geojson_map gives them).
std::vector<std::string> landmark_names(std::string_view map_document, const indoor_map::Map& map);

}  // namespace pednav::plot
