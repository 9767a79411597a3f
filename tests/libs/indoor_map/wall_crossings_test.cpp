// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <pednav_indoor_map/wall_crossings.hpp>

using namespace pednav::indoor_map;

TEST_CASE("wall crossings: steps through a wall of their floor, not of another, not while changing floor") {
    Map m;
    m.walls.push_back({{5, -2}, {5, 2}, 0, 3});   // a wall across the corridor on floor 0
    m.walls.push_back({{7, -2}, {7, 2}, 1, 4});   // and one on floor 1
    m.walls.push_back({{0, 1}, {10, 1}, 0, 5});   // the corridor's side
    const std::vector<Point2> track = {{0, 0}, {4, 0}, {6, 0}, {8, 0}, {8, 0.5}, {7.5, 0.5}, {6.5, 0}, {4, 3}};
    const std::vector<int> floors = {0, 0, 0, 0, 1, 1, 1, 0};
    const auto c = wall_crossings(m, track, floors);
    REQUIRE(c.size() == 2);
    CHECK(c[0].step == 2);  // (4, 0) -> (6, 0) through feature 3; (6, 0) -> (8, 0) passes feature 4 of floor 1
    CHECK(c[0].wall_feature == 3);
    CHECK(c[1].step == 6);  // (7.5, 0.5) -> (6.5, 0) on floor 1 through feature 4
    CHECK(c[1].wall_feature == 4);
    // All on floor 0: the last step, no longer a change of floor, goes through features 3 and 5.
    const auto flat = wall_crossings(m, track, {});
    REQUIRE(flat.size() == 3);
    CHECK(flat[0].step == 2);
    CHECK(flat[1].step == 7);
    CHECK(flat[1].wall_feature == 3);
    CHECK(flat[2].step == 7);
    CHECK(flat[2].wall_feature == 5);
}
