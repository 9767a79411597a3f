// SPDX-License-Identifier: Apache-2.0
#include "map_exercise.hpp"

#include <optional>
#include <vector>

#include "pednav_indoor_map/geojson_map.hpp"
#include "pednav_indoor_map/indexed_map.hpp"
#include "pednav_indoor_map/map_check.hpp"
#include "pednav_indoor_map/wall_crossings.hpp"

namespace pednav::fuzz {

void exercise_map(std::string_view document) {
    namespace im = pednav::indoor_map;
    std::optional<geodesy::GeodeticPoint> origin;
    try {
        origin = im::geojson_map_origin(document);
    } catch (const im::MapError&) {
        return;
    }
    // Without an origin of its own a WGS-84 map is read around the engine's (Bremen here).
    if (!origin) origin = geodesy::GeodeticPoint{53.1, 8.85, 0.0};
    im::MapCheckOptions check;
    check.start = im::MapStart{{0.0, 0.0}, 0};
    check.wall_clearance_m = 0.3;
    (void)im::check_map(document, origin, check);
    im::Map map;
    try {
        map = im::read_geojson_map(document, origin);
    } catch (const im::MapError&) {
        return;
    }
    const std::vector<im::Point2> track{{0.0, 0.0}, {3.0, 0.5}, {3.5, 4.0}, {-2.0, 6.0}};
    const std::vector<int> floors{0, 0, 1, 0};
    (void)im::wall_crossings(map, track, floors);
    const im::IndexedMap indexed(std::move(map), 2.0);
    (void)indexed.has_link(0, 1);
}

}  // namespace pednav::fuzz
