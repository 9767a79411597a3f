// SPDX-License-Identifier: Apache-2.0
// A building map in the engine's local frame: what a map matcher needs of a
// pednav.map/1 document (docs/maps.md), in metres east and north of the
// engine origin, per floor. Each element keeps the index of the GeoJSON
// feature it came from, so that errors and plots can name it.
#pragma once

#include <cmath>
#include <vector>

namespace pednav::indoor_map {

// A point in the local level frame, metres east and north of the origin.
struct Point2 {
    double e_m;
    double n_m;
};

// One straight piece of a wall (LineStrings and polygon rings are split into
// their segments).
struct WallSegment {
    Point2 a, b;
    int floor;
    int feature;  // index into the document's "features"
};

enum class ZoneKind {
    walkable,      // "zone": where a walker can be (rooms, corridors)
    no_particles,  // "no_particles": where a walker cannot be (voids, furniture, courtyards)
    altitude       // "altitude_zone": a place of known height, where barometric drift is reset
};

// A polygon: outer ring first, holes after; rings are closed implicitly (the
// last point is not repeated).
struct Zone {
    ZoneKind kind;
    int floor;
    std::vector<std::vector<Point2>> rings;
    double height_m;  // altitude zones: height of the floor there, m above the start level; NaN otherwise
    int feature;
};

enum class ConnectorKind { stairs, escalator, lift };

// Which way a connector may be taken, from `floor` to `floor_to`.
enum class ConnectorDirection {
    up,    // only from the lower floor to the higher one
    down,  // only from the higher floor to the lower one
    both
};

// Stairs, escalators and lifts, drawn as an arrow (a LineString from its foot
// on `floor` to its head on `floor_to`) or as an area (a Polygon) where the
// floor may change. `area` holds the polygon's outer ring, or for an arrow
// the arrow's points; `reach_m` is how far from it a walker counts as on it.
struct Connector {
    ConnectorKind kind;
    ConnectorDirection direction;
    int floor;
    int floor_to;
    bool is_arrow;
    std::vector<Point2> area;
    double reach_m;
    int feature;
};

// A named point (a landmark, a door, a start point) for checks and plots.
struct Landmark {
    Point2 p;
    int floor;
    int feature;
};

struct Map {
    std::vector<WallSegment> walls;
    std::vector<Zone> zones;
    std::vector<Connector> connectors;
    std::vector<Landmark> landmarks;
    std::vector<int> floors;    // every floor a feature is on, ascending
    double floor_height_m = std::nan("");  // from the document, NaN when it gives none
};

}  // namespace pednav::indoor_map
