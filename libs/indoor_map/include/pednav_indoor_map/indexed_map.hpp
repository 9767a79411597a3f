// SPDX-License-Identifier: Apache-2.0
// A map with its spatial indexes, ready for matching: the walls and zones in
// grids per floor (wall_index.hpp, zone_index.hpp) and the connectors with
// the tests a floor change needs.
#pragma once

#include "map.hpp"
#include "wall_index.hpp"
#include "zone_index.hpp"

namespace pednav::indoor_map {

// Whether connector c may take a walker from floor `from` to floor `to`:
// stairs and escalators join their two floors, a lift every floor from one
// to the other; and the direction allows the way (up: from the lower floor
// to the higher one).
bool connector_links(const Connector& c, int from, int to);

// Whether p (on the connector's floor) is on it: inside its area, or within
// reach_m of its outline (an area) or of its line (an arrow).
bool near_connector(const Connector& c, const Point2& p);

// Where a walker taken by c to floor `to` comes out: an escalator's or a
// lift's arrow carries the walker without steps to its head (or its foot,
// going the other way); on stairs the steps themselves carry the walker
// along the flight, and an area has the same footprint on both floors: there
// `p` itself is returned.
Point2 connector_exit(const Connector& c, int to, const Point2& p);

struct IndexedMap {
    IndexedMap(Map m, double cell_m);

    Map map;
    WallIndex walls;
    ZoneIndex zones;

    // Whether any connector links floor `from` to `to`.
    bool has_link(int from, int to) const;
};

}  // namespace pednav::indoor_map
