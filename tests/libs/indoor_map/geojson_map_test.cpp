// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include <pednav_indoor_map/geojson_map.hpp>

using namespace pednav::indoor_map;
using pednav::geodesy::GeodeticPoint;

namespace {

// The MapError a document raises, as "pointer | message".
std::string map_error(const std::string& doc, const std::optional<GeodeticPoint>& origin = std::nullopt) {
    try {
        read_geojson_map(doc, origin);
    } catch (const MapError& e) {
        return e.pointer + " | " + e.what();
    }
    return "no error";
}

std::string local_map(const std::string& features) {
    return R"({"type": "FeatureCollection", "pednav:crs": "local-enu", "features": [)" + features + "]}";
}

const char* const kBuilding = R"({
  "type": "FeatureCollection", "pednav:crs": "local-enu", "pednav:floor_height_m": 3.5,
  "features": [
    {"type": "Feature", "properties": {"pednav:kind": "wall", "pednav:floor": 0},
     "geometry": {"type": "LineString", "coordinates": [[0, 0], [10, 0], [10, 5]]}},
    {"type": "Feature", "properties": {"pednav:kind": "wall", "pednav:floor": 1},
     "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 3], [0, 3], [0, 0]]]}},
    {"type": "Feature", "properties": {"name": "a GIS extra"},
     "geometry": {"type": "Point", "coordinates": [1, 1]}},
    {"type": "Feature", "properties": {"pednav:kind": "zone", "pednav:floor": 0},
     "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 5], [0, 5]],
                                                     [[4, 2], [5, 2], [5, 3], [4, 3]]]}},
    {"type": "Feature", "properties": {"pednav:kind": "no_particles", "pednav:floor": 0},
     "geometry": {"type": "Polygon", "coordinates": [[[6, 1], [7, 1], [7, 2], [6, 2]]]}},
    {"type": "Feature", "properties": {"pednav:kind": "altitude_zone", "pednav:floor": 1, "pednav:height_m": 3.6},
     "geometry": {"type": "Polygon", "coordinates": [[[1, 1], [2, 1], [2, 2]]]}},
    {"type": "Feature", "properties": {"pednav:kind": "stairs", "pednav:floor": 0, "pednav:floor_to": 1,
                                       "pednav:direction": "up"},
     "geometry": {"type": "LineString", "coordinates": [[8, 1], [8, 4]]}},
    {"type": "Feature", "properties": {"pednav:kind": "lift", "pednav:floor": -1, "pednav:floor_to": 1,
                                       "pednav:reach_m": 0.5},
     "geometry": {"type": "Polygon", "coordinates": [[[9, 4], [10, 4], [10, 5], [9, 5]]]}},
    {"type": "Feature", "properties": {"pednav:kind": "escalator", "pednav:floor": 1, "pednav:floor_to": 0,
                                       "pednav:direction": "down"},
     "geometry": {"type": "LineString", "coordinates": [[3, 1], [3, 2]]}},
    {"type": "Feature", "properties": {"pednav:kind": "landmark", "pednav:floor": 0, "name": "door"},
     "geometry": {"type": "Point", "coordinates": [2.5, 4.5]}}
  ]})";

}  // namespace

TEST_CASE("geojson map: every kind in local metres, with its feature index") {
    const Map m = read_geojson_map(kBuilding, std::nullopt);
    REQUIRE(m.walls.size() == 2 + 4);  // a LineString of 3 points, a closed ring of 4
    CHECK(m.walls[1].a.e_m == 10.0);
    CHECK(m.walls[1].b.n_m == 5.0);
    CHECK(m.walls[1].feature == 0);
    CHECK(m.walls[5].a.e_m == 0.0);  // the ring's closing edge (0,3) -> (0,0)
    CHECK(m.walls[5].a.n_m == 3.0);
    CHECK(m.walls[5].floor == 1);
    REQUIRE(m.zones.size() == 3);
    CHECK(m.zones[0].kind == ZoneKind::walkable);
    CHECK(m.zones[0].rings.size() == 2);
    CHECK(m.zones[0].feature == 3);
    CHECK(std::isnan(m.zones[0].height_m));
    CHECK(m.zones[1].kind == ZoneKind::no_particles);
    CHECK(m.zones[1].rings[0].size() == 4);  // unclosed ring kept as it is
    CHECK(m.zones[2].kind == ZoneKind::altitude);
    CHECK(m.zones[2].height_m == 3.6);
    REQUIRE(m.connectors.size() == 3);
    CHECK(m.connectors[0].kind == ConnectorKind::stairs);
    CHECK(m.connectors[0].direction == ConnectorDirection::up);
    CHECK(m.connectors[0].is_arrow);
    CHECK(m.connectors[0].area.size() == 2);
    CHECK(m.connectors[0].reach_m == 1.0);
    CHECK(m.connectors[1].kind == ConnectorKind::lift);
    CHECK(m.connectors[1].direction == ConnectorDirection::both);
    CHECK(!m.connectors[1].is_arrow);
    CHECK(m.connectors[1].area.size() == 4);
    CHECK(m.connectors[1].reach_m == 0.5);
    CHECK(m.connectors[1].floor == -1);
    CHECK(m.connectors[2].kind == ConnectorKind::escalator);
    CHECK(m.connectors[2].direction == ConnectorDirection::down);
    CHECK(m.connectors[2].feature == 8);
    REQUIRE(m.landmarks.size() == 1);
    CHECK(m.landmarks[0].p.e_m == 2.5);
    CHECK(m.landmarks[0].feature == 9);
    CHECK(m.floors == std::vector<int>{-1, 0, 1});
    CHECK(m.floor_height_m == 3.5);
}

TEST_CASE("geojson map: WGS-84 through the engine origin, else the map's own") {
    const GeodeticPoint origin{48.1, 11.5, 500.0};
    double lat = 0, lon = 0, h = 0;
    const double enu[3] = {30.0, -20.0, 0.0};
    pednav::geodesy::enu_to_geodetic(origin, enu, &lat, &lon, &h);
    std::ostringstream lonlat;
    lonlat << std::setprecision(15) << "[" << lon << ", " << lat << ", " << h << "]";
    std::ostringstream ring;
    ring << std::setprecision(15) << "[[11.5, 48.1], [" << lon << ", 48.1], [" << lon << ", " << lat << "]]";
    const std::string features = R"("features": [
          {"type": "Feature", "properties": {"pednav:kind": "wall", "pednav:floor": 2},
           "geometry": {"type": "LineString", "coordinates": [[11.5, 48.1, 500], )" + lonlat.str() + R"(]}},
          {"type": "Feature", "properties": {"pednav:kind": "altitude_zone", "pednav:floor": 2, "pednav:height_m": 507},
           "geometry": {"type": "Polygon", "coordinates": [)" + ring.str() + "]}}]}";
    const std::string with_origin = R"({"type": "FeatureCollection", "pednav:origin": [11.5, 48.1, 500], )" + features;
    const std::string without = R"({"type": "FeatureCollection", )" + features;

    const Map m = read_geojson_map(without, origin);
    REQUIRE(m.walls.size() == 1);
    CHECK(m.walls[0].a.e_m == doctest::Approx(0.0).epsilon(1e-9));
    CHECK(m.walls[0].b.e_m == doctest::Approx(30.0).epsilon(1e-9));
    CHECK(m.walls[0].b.n_m == doctest::Approx(-20.0).epsilon(1e-9));
    CHECK(m.zones[0].height_m == doctest::Approx(7.0).epsilon(1e-6));
    CHECK(m.floors == std::vector<int>{2});

    const Map own = read_geojson_map(with_origin, std::nullopt);
    CHECK(own.walls[0].b.e_m == doctest::Approx(30.0).epsilon(1e-9));
    REQUIRE(geojson_map_origin(with_origin).has_value());
    CHECK(geojson_map_origin(with_origin)->lat_deg == 48.1);
    CHECK(geojson_map_origin(with_origin)->height_m == 500.0);
    CHECK(!geojson_map_origin(without).has_value());

    // Another engine origin 100 m east: the same wall lies 100 m further west.
    double lat2 = 0, lon2 = 0, h2 = 0;
    const double east[3] = {100.0, 0.0, 0.0};
    pednav::geodesy::enu_to_geodetic(origin, east, &lat2, &lon2, &h2);
    const Map moved = read_geojson_map(with_origin, GeodeticPoint{lat2, lon2, h2});
    CHECK(moved.walls[0].b.e_m == doctest::Approx(-70.0).epsilon(1e-5));  // the other tangent plane: 0.3 mm

    CHECK(map_error(without) ==
          " | the map is in WGS-84 degrees and neither the engine nor the map (pednav:origin) has an origin; set one "
          "or give the map \"pednav:crs\": \"local-enu\"");
}

TEST_CASE("geojson map: local metres of the map's own origin move to another engine origin") {
    const std::string doc = R"({"type": "FeatureCollection", "pednav:crs": "local-enu", "pednav:origin": [11.5, 48.1, 500],
        "features": [{"type": "Feature", "properties": {"pednav:kind": "landmark", "pednav:floor": 0},
                      "geometry": {"type": "Point", "coordinates": [10, 5]}}]})";
    CHECK(read_geojson_map(doc, std::nullopt).landmarks[0].p.e_m == 10.0);
    CHECK(read_geojson_map(doc, GeodeticPoint{48.1, 11.5, 500.0}).landmarks[0].p.e_m == 10.0);
    double lat = 0, lon = 0, h = 0;
    const double east[3] = {4.0, -3.0, 0.0};
    pednav::geodesy::enu_to_geodetic({48.1, 11.5, 500.0}, east, &lat, &lon, &h);
    const Map m = read_geojson_map(doc, GeodeticPoint{lat, lon, h});
    CHECK(m.landmarks[0].p.e_m == doctest::Approx(6.0).epsilon(1e-6));
    CHECK(m.landmarks[0].p.n_m == doctest::Approx(8.0).epsilon(1e-6));
}

TEST_CASE("geojson map: the simulator's earlier building.geojson loads as it is") {
    // Written by pednav sim before pednav.map/1: plain "kind"/"floor", the
    // route as a LineString of kind "route", the origin as an object.
    const std::string doc = R"({
 "features": [
  {"geometry": {"coordinates": [[2.3522, 48.8566], [2.3530, 48.8566]], "type": "LineString"},
   "properties": {"floor": 1, "kind": "wall"}, "type": "Feature"},
  {"geometry": {"coordinates": [[2.3522, 48.8566], [2.3525, 48.8567]], "type": "LineString"},
   "properties": {"kind": "route", "name": "stairs"}, "type": "Feature"}
 ],
 "pednav:origin": {"height_m": 50.0, "lat_deg": 48.8566, "lon_deg": 2.3522},
 "type": "FeatureCollection"
})";
    const Map m = read_geojson_map(doc, std::nullopt);
    REQUIRE(m.walls.size() == 1);
    CHECK(m.walls[0].floor == 1);
    CHECK(m.walls[0].b.e_m == doctest::Approx(58.7).epsilon(0.01));
    CHECK(std::fabs(m.walls[0].b.n_m) < 0.01);
    CHECK(m.floors == std::vector<int>{1});
    CHECK(geojson_map_origin(doc)->lon_deg == 2.3522);
}

TEST_CASE("geojson map: errors name the member at fault by JSON pointer") {
    const std::string wall = R"({"type": "Feature", "properties": {"pednav:kind": "wall", "pednav:floor": 0},
                                 "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]}})";
    CHECK(map_error("{") == " | not valid JSON at line 1, column 2: syntax error while parsing object key - unexpected end of input; "
                             "expected string literal");
    CHECK(map_error(R"({"type": "FeatureCollection", "type": "x", "features": []})") ==
          "/type | duplicate key \"type\" in the document");
    std::string deepest = "/features";  // the 65th level: the document, its features and 63 arrays in them
    for (int level = 0; level < 63; ++level) deepest += "/0";
    CHECK(map_error(R"({"type": "FeatureCollection", "features": [)" + std::string(70, '[')) ==
          deepest + " | arrays and objects nested deeper than 64 levels at " + deepest);
    CHECK(map_error(R"({"type": "Feature"})") ==
          "/type | the map is not a GeoJSON FeatureCollection (\"type\": \"FeatureCollection\")");
    CHECK(map_error(R"({"type": "FeatureCollection"})") == "/features | a FeatureCollection needs a \"features\" array");
    CHECK(map_error(R"({"type": "FeatureCollection", "pednav:crs": "utm", "features": []})") ==
          "/pednav:crs | unknown pednav:crs \"utm\" (wgs84 or local-enu)");
    CHECK(map_error(local_map(wall + R"(, {"properties": {"pednav:kind": "door", "pednav:floor": 0}})")) ==
          "/features/1/properties/pednav:kind | unknown pednav:kind \"door\" (wall, zone, no_particles, altitude_zone, "
          "stairs, escalator, lift or landmark)");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "wall"}})")) ==
          "/features/0/properties/pednav:floor | pednav:floor is missing");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "wall", "pednav:floor": 0.5}})")) ==
          "/features/0/properties/pednav:floor | pednav:floor is not an integer: 0.5");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "wall", "pednav:floor": 0}})")) ==
          "/features/0/geometry | a wall needs a geometry (LineString or Polygon)");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "zone", "pednav:floor": 0},
                                  "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]}})")) ==
          "/features/0/geometry/type | a zone is a Polygon, not a LineString");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "wall", "pednav:floor": 0},
                                  "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0], [2, "x"]]}})")) ==
          "/features/0/geometry/coordinates/2/1 | not a number: \"x\"");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "wall", "pednav:floor": 0},
                                  "geometry": {"type": "LineString", "coordinates": [[0, 0]]}})")) ==
          "/features/0/geometry/coordinates | a LineString needs at least 2 positions, got 1");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "zone", "pednav:floor": 0},
                                  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 0]]]}})")) ==
          "/features/0/geometry/coordinates/0 | a ring needs at least 3 positions besides the closing one, got 2");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "altitude_zone", "pednav:floor": 0},
                                  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}})")) ==
          "/features/0/properties/pednav:height_m | pednav:height_m is missing");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "stairs", "pednav:floor": 0, "pednav:floor_to": 0},
                                  "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]}})")) ==
          "/features/0/properties/pednav:floor_to | pednav:floor_to is pednav:floor (0): a stairs connects two floors");
    CHECK(map_error(local_map(R"({"properties": {"pednav:kind": "lift", "pednav:floor": 0, "pednav:floor_to": 2,
                                                 "pednav:direction": "sideways"},
                                  "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]}})")) ==
          "/features/0/properties/pednav:direction | unknown pednav:direction \"sideways\" (up, down or both)");
    CHECK(map_error(R"({"type": "FeatureCollection", "pednav:origin": [11.5, 48.1, 500], "features": [{"properties":
          {"pednav:kind": "landmark", "pednav:floor": 0}, "geometry": {"type": "Point", "coordinates": [11.5, 98.1]}}]})") ==
          "/features/0/geometry/coordinates/1 | latitude 98.1 is beyond 90 degrees");
    CHECK(map_error(R"({"type": "FeatureCollection", "pednav:origin": [11.5], "features": []})") ==
          "/pednav:origin | pednav:origin is [longitude, latitude] or [longitude, latitude, height], got [11.5]");
    CHECK(map_error(R"({"type": "FeatureCollection", "pednav:crs": "local-enu", "pednav:floor_height_m": 0,
                        "features": []})") ==
          "/pednav:floor_height_m | pednav:floor_height_m = 0 is outside [0.5, 100.0]");
}
