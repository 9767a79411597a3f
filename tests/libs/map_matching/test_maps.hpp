// SPDX-License-Identifier: Apache-2.0
// Small maps built in code for the map-matching tests, and the filter's
// config from the map matcher plugin's parameter defaults.
#pragma once

#include <pednav_indoor_map/map.hpp>
#include <pednav_map_matching/map_matcher.hpp>

#include "../plugin_defaults.hpp"

namespace pednav::test {

inline map_matching::MapMatcherConfig matcher_defaults() {
    PluginDefaults d("libpnp_map_particle_filter.so", "org.pednav.map.particle_filter");
    return map_matching::map_matcher_config(d);
}

inline void add_polyline(indoor_map::Map& m, int floor, std::vector<indoor_map::Point2> pts) {
    for (size_t i = 0; i + 1 < pts.size(); ++i)
        m.walls.push_back({pts[i], pts[i + 1], floor, static_cast<int>(m.walls.size())});
}

// A corridor 2 m wide from x = 0 to x = length along y in [0, 2], closed at both ends.
inline indoor_map::Map corridor_map(double length_m, int floor = 0) {
    indoor_map::Map m;
    add_polyline(m, floor, {{0, 0}, {length_m, 0}, {length_m, 2}, {0, 2}, {0, 0}});
    m.floors = {floor};
    return m;
}

// An L: east along y in [0, 2] to x = 20, then north along x in [18, 20] to y = 20.
inline indoor_map::Map l_corridor_map() {
    indoor_map::Map m;
    add_polyline(m, 0, {{0, 0}, {20, 0}, {20, 20}, {18, 20}, {18, 2}, {0, 2}, {0, 0}});
    m.floors = {0};
    return m;
}

inline indoor_map::Connector stairs_area(int floor, int floor_to, std::vector<indoor_map::Point2> ring,
                                         indoor_map::ConnectorDirection dir = indoor_map::ConnectorDirection::both) {
    return {indoor_map::ConnectorKind::stairs, dir, floor, floor_to, false, std::move(ring), 0.5, 0};
}

}  // namespace pednav::test
