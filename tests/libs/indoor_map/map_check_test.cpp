// SPDX-License-Identifier: Apache-2.0
// One broken map per problem map check finds, each with its exact message and
// JSON pointer; and a sound map with none.
#include <doctest/doctest.h>

#include <string>

#include <pednav_indoor_map/map_check.hpp>

using namespace pednav::indoor_map;

namespace {

// A 10 m x 6 m room on floor 0 (features 0 and 1) and its twin on floor 1
// (features 2 and 3), then `more` features.
std::string building(const std::string& more = "") {
    return R"({"type": "FeatureCollection", "pednav:crs": "local-enu", "features": [
      {"properties": {"pednav:kind": "wall", "pednav:floor": 0},
       "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]]}},
      {"properties": {"pednav:kind": "zone", "pednav:floor": 0},
       "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6]]]}},
      {"properties": {"pednav:kind": "wall", "pednav:floor": 1},
       "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6]]]}},
      {"properties": {"pednav:kind": "zone", "pednav:floor": 1},
       "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 6], [0, 6]]]}})" +
           more + "]}";
}

MapCheckOptions no_start() { return {std::nullopt, 0.3}; }
MapCheckOptions start_at(double e, double n, int floor) { return {MapStart{{e, n}, floor}, 0.3}; }

// The one problem a document has, as "feature | pointer | message".
std::string only_problem(const std::string& doc, const MapCheckOptions& options = no_start()) {
    const auto p = check_map(doc, std::nullopt, options);
    if (p.size() != 1) return std::to_string(p.size()) + " problems";
    return std::to_string(p[0].feature) + " | " + p[0].pointer + " | " + p[0].message;
}

}  // namespace

TEST_CASE("map check: a sound map with stairs between its floors and a good start has no problem") {
    const std::string doc = building(R"(, {"properties": {"pednav:kind": "stairs", "pednav:floor": 0,
        "pednav:floor_to": 1, "pednav:direction": "up"}, "geometry": {"type": "LineString", "coordinates": [[8, 1], [8, 5]]}})");
    CHECK(check_map(doc, std::nullopt, start_at(2, 3, 0)).empty());
    CHECK(check_map(doc, std::nullopt, start_at(5, 3, 1)).empty());
}

TEST_CASE("map check: a self-crossing polygon") {
    CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "no_particles", "pednav:floor": 0},
            "geometry": {"type": "Polygon", "coordinates": [[[2, 2], [4, 4], [4, 2], [2, 4], [2, 2]]]}})")) ==
          "4 | /features/4/geometry/coordinates/0/0 | no_particles feature 4: ring 0 crosses itself: edges 0 and 2 meet");
}

TEST_CASE("map check: an unknown kind") {
    CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "window", "pednav:floor": 0},
            "geometry": {"type": "LineString", "coordinates": [[2, 0], [4, 0]]}})")) ==
          "4 | /features/4/properties/pednav:kind | unknown pednav:kind \"window\" (wall, zone, no_particles, "
          "altitude_zone, stairs, escalator, lift or landmark)");
}

TEST_CASE("map check: an arrow to a floor that does not exist") {
    CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "lift", "pednav:floor": 1, "pednav:floor_to": 4},
            "geometry": {"type": "LineString", "coordinates": [[9, 5], [9, 5.5]]}})")) ==
          "4 | /features/4/properties/pednav:floor_to | lift feature 4: pednav:floor_to 4 is a floor with no wall, zone "
          "or landmark");
}

TEST_CASE("map check: an arrow from a floor that does not exist") {
    CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "escalator", "pednav:floor": -1, "pednav:floor_to": 0},
            "geometry": {"type": "Polygon", "coordinates": [[[1, 1], [2, 1], [2, 2]]]}})")) ==
          "4 | /features/4/properties/pednav:floor | escalator feature 4: pednav:floor -1 is a floor with no wall, zone "
          "or landmark");
}

TEST_CASE("map check: an arrow drawn against its direction") {
    CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "escalator", "pednav:floor": 1, "pednav:floor_to": 0,
            "pednav:direction": "up"}, "geometry": {"type": "LineString", "coordinates": [[1, 1], [1, 4]]}})")) ==
          "4 | /features/4/properties/pednav:direction | escalator feature 4: pednav:direction up, but its arrow goes "
          "down from floor 1 to floor 0");
}

TEST_CASE("map check: degenerate geometry") {
    SUBCASE("a wall whose positions coincide") {
        CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "wall", "pednav:floor": 0},
                "geometry": {"type": "LineString", "coordinates": [[3, 3], [3, 3]]}})")) ==
              "4 | /features/4/geometry/coordinates | wall feature 4: its positions coincide (no length)");
    }
    SUBCASE("a wall with a repeated position") {
        CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "wall", "pednav:floor": 0},
                "geometry": {"type": "LineString", "coordinates": [[3, 3], [4, 3], [4, 3], [4, 4]]}})")) ==
              "4 | /features/4/geometry/coordinates/2 | wall feature 4: positions 1 and 2 coincide");
    }
    SUBCASE("a zone of no area") {
        CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "zone", "pednav:floor": 1},
                "geometry": {"type": "Polygon", "coordinates": [[[1, 1], [2, 2], [3, 3], [1, 1]]]}})")) ==
              "4 | /features/4/geometry/coordinates/0 | zone feature 4: ring 0 has no area (its positions are on one line)");
    }
    SUBCASE("a hole with a repeated position") {
        CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "zone", "pednav:floor": 1},
                "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [5, 0], [5, 5], [0, 5]],
                                                                [[1, 1], [2, 1], [2, 1], [2, 2]]]}})")) ==
              "4 | /features/4/geometry/coordinates/1/2 | zone feature 4: ring 1: positions 1 and 2 coincide");
    }
}

TEST_CASE("map check: a start point inside a wall's clearance") {
    CHECK(only_problem(building(), start_at(9.8, 3, 0)) ==
          "0 | /features/0/geometry | the start (9.80, 3.00) on floor 0 is 0.20 m from wall feature 0, within its "
          "clearance of 0.30 m");
}

TEST_CASE("map check: a start point in a no-particle zone") {
    CHECK(only_problem(building(R"(, {"properties": {"pednav:kind": "no_particles", "pednav:floor": 1},
            "geometry": {"type": "Polygon", "coordinates": [[[4, 2], [6, 2], [6, 4], [4, 4]]]}})"),
                       start_at(5, 3, 1)) ==
          "4 | /features/4/geometry | the start (5.00, 3.00) on floor 1 is inside no_particles feature 4");
}

TEST_CASE("map check: a start point outside every walkable zone") {
    CHECK(only_problem(building(), start_at(14, 3, 1)) ==
          "3 | /features/3/geometry | the start (14.00, 3.00) on floor 1 is outside every zone of its floor; the "
          "nearest, zone feature 3, is 4.00 m away");
}

TEST_CASE("map check: a start point outside the walls of a floor without zones") {
    const std::string walls_only = R"({"type": "FeatureCollection", "pednav:crs": "local-enu", "features": [
      {"properties": {"pednav:kind": "wall", "pednav:floor": 0},
       "geometry": {"type": "LineString", "coordinates": [[0, 0], [10, 0], [10, 6]]}}]})";
    CHECK(check_map(walls_only, std::nullopt, start_at(5, 3, 0)).empty());
    CHECK(only_problem(walls_only, start_at(-4, 3, 0)) ==
          "-1 |  | the start (-4.00, 3.00) on floor 0 is outside the walls of its floor (east 0.00 to 10.00 m, north "
          "0.00 to 6.00 m)");
}

TEST_CASE("map check: a start point on a floor the map does not have") {
    CHECK(only_problem(building(), start_at(5, 3, 3)) == "-1 |  | the start (5.00, 3.00) is on floor 3, where the map has nothing");
}

TEST_CASE("map check: a document that cannot be read is its one problem") {
    CHECK(only_problem(R"({"type": "FeatureCollection", "features": [{"properties": {"pednav:kind": "wall",
            "pednav:floor": 0}, "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 0]]}}]})") ==
          "-1 |  | the map is in WGS-84 degrees and neither the engine nor the map (pednav:origin) has an origin; set "
          "one or give the map \"pednav:crs\": \"local-enu\"");
}

TEST_CASE("map check: several problems are all reported, each with its feature") {
    const auto p = check_map(building(R"(, {"properties": {"pednav:kind": "wall", "pednav:floor": 0},
            "geometry": {"type": "LineString", "coordinates": [[3, 3], [3, 3]]}},
        {"properties": {"pednav:kind": "stairs", "pednav:floor": 0, "pednav:floor_to": 7},
            "geometry": {"type": "LineString", "coordinates": [[8, 1], [8, 5]]}})"),
                             std::nullopt, start_at(3.1, 3, 0));
    REQUIRE(p.size() == 3);
    CHECK(p[0].feature == 4);
    CHECK(p[1].feature == 5);
    CHECK(p[1].pointer == "/features/5/properties/pednav:floor_to");
    CHECK(p[2].feature == 4);  // the start is 0.10 m from the degenerate wall
    CHECK(p[2].message == "the start (3.10, 3.00) on floor 0 is 0.10 m from wall feature 4, within its clearance of 0.30 m");
}
