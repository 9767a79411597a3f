// SPDX-License-Identifier: Apache-2.0
// What is wrong with a pednav.map/1 document beyond what stops it being read:
// rings that cross themselves, geometry of no length or area, connectors to
// floors nothing is on, arrows drawn against their direction, and a start
// point a walker could not stand on. Each problem names its feature.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pednav_geodesy/enu.hpp>

#include "map.hpp"

namespace pednav::indoor_map {

struct MapProblem {
    int feature;          // index into "features", -1 for the document as a whole
    std::string pointer;  // JSON pointer into the document
    std::string message;
};

// Where a walk starts, in the engine's frame.
struct MapStart {
    Point2 p;
    int floor;
};

struct MapCheckOptions {
    std::optional<MapStart> start;  // checked when given
    double wall_clearance_m;        // a start closer than this to a wall is inside it
};

// Every problem of the document (its geometry, then its connectors, then the
// start), each naming its feature; empty when it is sound. A
// document that cannot be read gives its one MapError as the only problem.
std::vector<MapProblem> check_map(std::string_view document, const std::optional<geodesy::GeodeticPoint>& origin,
                                  const MapCheckOptions& options);

}  // namespace pednav::indoor_map
