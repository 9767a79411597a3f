// SPDX-License-Identifier: Apache-2.0
// The pednav.map/1 GeoJSON map format (docs/maps.md) read into the
// local-metre building model of map.hpp.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <pednav_geodesy/enu.hpp>

#include "map.hpp"

namespace pednav::indoor_map {

// A map document that is wrong: `pointer` is a JSON pointer into the document
// naming the feature at fault ("/features/12/geometry/coordinates/3"), what()
// says what is wrong with it.
struct MapError : std::runtime_error {
    std::string pointer;
    MapError(std::string pointer, const std::string& message);
};

// The document's own origin (top-level "pednav:origin" [lon, lat, height]),
// if it has one. Throws MapError when it is malformed.
std::optional<geodesy::GeodeticPoint> geojson_map_origin(std::string_view document);

// Reads a pednav.map/1 document (docs/maps.md) into the local-metre model of
// map.hpp. `origin`: the engine's geodetic origin (nullopt when it has none:
// then the document's own origin is used; a WGS-84 map with neither throws).
// Maps in local metres (top-level "pednav:crs": "local-enu", coordinates
// [east_m, north_m]) need no origin.
Map read_geojson_map(std::string_view document, const std::optional<geodesy::GeodeticPoint>& origin);

}  // namespace pednav::indoor_map
