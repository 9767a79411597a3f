// SPDX-License-Identifier: Apache-2.0
// The output's place in the cloud and its way round walls (cloud_route.hpp)
// on maps built in code.
#include <doctest/doctest.h>

#include <cmath>

#include <pednav_map_matching/cloud_route.hpp>

#include "test_maps.hpp"

using namespace pednav;
using namespace pednav::map_matching;
using indoor_map::IndexedMap;

namespace {

Particle at(double e, double n) {
    Particle p{};
    p.e_m = e;
    p.n_m = n;
    p.cos_h = 1.0;
    p.scale = 1.0;
    return p;
}

// A corridor along y in [0, 2] from x = 0 to 20 and a room above it, y in
// [2.1, 6], joined by a door at x in [14, 15].
indoor_map::Map corridor_and_room() {
    indoor_map::Map m;
    test::add_polyline(m, 0, {{0, 0}, {20, 0}, {20, 6}, {0, 6}, {0, 0}});
    test::add_polyline(m, 0, {{0, 2}, {14, 2}});
    test::add_polyline(m, 0, {{15, 2}, {20, 2}});
    m.floors = {0};
    return m;
}

}  // namespace

TEST_CASE("the output is the largest group's particle nearest the group's mean") {
    const IndexedMap map(corridor_and_room(), 2.0);
    std::vector<Particle> cloud;
    for (int i = 0; i < 260; ++i) cloud.push_back(at(4.0 + 0.01 * i, 0.6 + 0.002 * i));   // corridor
    for (int i = 0; i < 240; ++i) cloud.push_back(at(4.0 + 0.015 * i, 2.3 + 0.004 * i));  // room
    CloudRoute route(1.0, 500, 16);
    route.index(cloud);
    const int k = route.mode_particle(&map.walls, 0, cloud);
    REQUIRE(k >= 0);
    const Particle& p = cloud[static_cast<size_t>(k)];
    CHECK(std::fabs(p.e_m - 5.3) < 0.1);  // at the corridor group's mean (5.3, 0.86)
    CHECK(std::fabs(p.n_m - 0.86) < 0.1);
    // Without the wall the cells join into one group: the particle nearest
    // the whole cloud's mean (5.5, 1.78).
    double se = 0, sn = 0;
    for (const Particle& q : cloud) se += q.e_m, sn += q.n_m;
    const Point2 mean{se / 500, sn / 500};
    size_t nearest_mean = 0;
    for (size_t i = 0; i < cloud.size(); ++i)
        if (std::hypot(cloud[i].e_m - mean.e_m, cloud[i].n_m - mean.n_m) <
            std::hypot(cloud[nearest_mean].e_m - mean.e_m, cloud[nearest_mean].n_m - mean.n_m))
            nearest_mean = i;
    CHECK(route.mode_particle(nullptr, 0, cloud) == static_cast<int>(nearest_mean));
    CHECK(static_cast<int>(nearest_mean) != k);
}

TEST_CASE("an output that cannot see the estimate goes round through the cloud, crossing no wall") {
    const IndexedMap map(corridor_and_room(), 2.0);
    std::vector<Particle> cloud;  // along the room, through the door, along the corridor
    for (double x = 4.0; x <= 14.5; x += 0.25) cloud.push_back(at(x, 3.5));
    for (double y = 3.5; y >= 1.0; y -= 0.25) cloud.push_back(at(14.5, y));
    for (double x = 14.5; x >= 4.0; x -= 0.25) cloud.push_back(at(x, 1.0));
    CloudRoute route(1.0, static_cast<int>(cloud.size()), 16);
    route.index(cloud);
    Point2 output{4.0, 3.5};
    const Point2 goal{4.0, 1.0};  // right below, behind the wall
    REQUIRE(map.walls.crosses_wall(0, output, goal));
    int moves = 0;
    while (map.walls.crosses_wall(0, output, goal) && moves < 20) {
        Point2 next;
        REQUIRE(route.next_waypoint(map.walls, 0, output, goal, next));
        CHECK_FALSE(map.walls.crosses_wall(0, output, next));
        output = next;
        ++moves;
    }
    CHECK(moves <= 3);  // to the door and out of it, then the goal is in sight
    CHECK_FALSE(map.walls.crosses_wall(0, output, goal));
}

TEST_CASE("an output the cloud has left retraces its own track to where it sees the cloud") {
    const IndexedMap map(corridor_and_room(), 2.0);
    CloudRoute route(1.0, 64, 32);
    // The output went along the corridor, through the door and into the room.
    for (const Point2& p : {Point2{10, 1}, Point2{14.5, 1}, Point2{14.5, 3}, Point2{12, 4}, Point2{8, 5}})
        route.record_output(p);
    std::vector<Particle> cloud;  // the cloud is in the corridor, west of the door
    for (double x = 5.0; x <= 9.0; x += 0.25) cloud.push_back(at(x, 1.0));
    route.index(cloud);
    Point2 output{8, 5};
    const Point2 goal{7, 1};
    Point2 next;
    REQUIRE(route.next_waypoint(map.walls, 0, output, goal, next));
    CHECK_FALSE(map.walls.crosses_wall(0, output, next));
    output = next;
    // Back at the door, where the corridor is in sight, in at most two moves.
    if (map.walls.crosses_wall(0, output, goal)) {
        REQUIRE(route.next_waypoint(map.walls, 0, output, goal, next));
        CHECK_FALSE(map.walls.crosses_wall(0, output, next));
        output = next;
    }
    CHECK(output.n_m <= 3.0);
    CHECK(output.e_m == doctest::Approx(14.5));
}
