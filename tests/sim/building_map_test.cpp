// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>

#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_indoor_map/geometry_2d.hpp>
#include <pednav_sim/building_map.hpp>

using namespace pednav;
using indoor_map::Point2;

namespace {

indoor_map::Map route_map(const sim::Route& r) {
    return indoor_map::read_geojson_map(sim::building_map(r).dump(), std::nullopt);
}

int floor_of(const sim::Route& r, double z) { return static_cast<int>(std::lround(z / r.floor_height_m)); }

// Path segments of the route that cross a wall on a floor either end is on.
int path_wall_crossings(const sim::Route& r, const indoor_map::Map& m) {
    int n = 0;
    for (size_t i = 1; i < r.waypoints.size(); ++i) {
        const double *a = r.waypoints[i - 1].enu_m, *b = r.waypoints[i].enu_m;
        for (const auto& w : m.walls)
            if ((w.floor == floor_of(r, a[2]) || w.floor == floor_of(r, b[2])) &&
                indoor_map::segments_intersect({a[0], a[1]}, {b[0], b[1]}, w.a, w.b))
                ++n;
    }
    return n;
}

}  // namespace

TEST_CASE("building map: every built-in route's map loads, and its path goes through doors, not walls") {
    for (const std::string& name : sim::builtin_route_names()) {
        CAPTURE(name);
        const sim::Route r = sim::builtin_route(name);
        const indoor_map::Map m = route_map(r);
        CHECK(m.floor_height_m == r.floor_height_m);
        REQUIRE(m.landmarks.size() == 1);
        CHECK(std::hypot(m.landmarks[0].p.e_m - r.waypoints[0].enu_m[0], m.landmarks[0].p.n_m - r.waypoints[0].enu_m[1]) <
              1e-6);
        size_t wall_points = 0;
        for (const auto& w : r.walls) wall_points += w.points_enu_m.size() - 1;
        CHECK(m.walls.size() >= wall_points);  // doorways split walls into more pieces
        CHECK(path_wall_crossings(r, m) == 0);
    }
}

TEST_CASE("building map: building_tour gets doorways into its stairwell and its two flights as stairs arrows") {
    const sim::Route r = sim::builtin_route("building_tour");
    const indoor_map::Map m = route_map(r);
    CHECK(m.floors == std::vector<int>{0, 1, 2});
    // Twelve crossings of the corridor and stairwell walls, at two places per floor on floors 1 and 2
    // ((8, -1.25) and (8, -0.75)) and at (10, -1.25) and (10, -0.75) on floor 0: each a 1 m gap.
    double removed_m = 0;
    size_t original_walls = 0;
    for (const auto& w : r.walls) original_walls += w.points_enu_m.size() - 1;
    double original_m = 0, mapped_m = 0;
    for (const auto& w : r.walls)
        for (size_t k = 0; k + 1 < w.points_enu_m.size(); ++k)
            original_m += std::hypot(w.points_enu_m[k + 1][0] - w.points_enu_m[k][0],
                                     w.points_enu_m[k + 1][1] - w.points_enu_m[k][1]);
    for (const auto& w : m.walls) mapped_m += std::hypot(w.b.e_m - w.a.e_m, w.b.n_m - w.a.n_m);
    removed_m = original_m - mapped_m;
    CHECK(removed_m == doctest::Approx(6 * sim::kDoorWidthM).epsilon(1e-4));
    CHECK(m.walls.size() == original_walls + 6);
    REQUIRE(m.connectors.size() == 2);
    for (int k = 0; k < 2; ++k) {
        const auto& c = m.connectors[k];
        CHECK(c.kind == indoor_map::ConnectorKind::stairs);
        CHECK(c.direction == indoor_map::ConnectorDirection::both);
        CHECK(c.is_arrow);
        CHECK(c.floor == k);
        CHECK(c.floor_to == k + 1);
        REQUIRE(c.area.size() == 4);  // the U: flight, landing, flight
    }
    // Floor 0 -> 1 climbs from (10, -1.5) to (10, -3).
    CHECK(m.connectors[0].area.front().e_m == doctest::Approx(10.0).epsilon(1e-6));
    CHECK(m.connectors[0].area.front().n_m == doctest::Approx(-1.5).epsilon(1e-6));
    CHECK(m.connectors[0].area.back().n_m == doctest::Approx(-3.0).epsilon(1e-6));
}

TEST_CASE("building map: the stairs route has one flight, a single-floor route none") {
    CHECK(route_map(sim::builtin_route("stairs")).connectors.size() == 1);
    CHECK(route_map(sim::builtin_route("corridor_loop")).connectors.empty());
    CHECK(route_map(sim::builtin_route("corridor_loop")).floors == std::vector<int>{0});
}

TEST_CASE("building map: altitude zones along the level stretches of a multi-floor route, at their floor's height") {
    const sim::Route r = sim::builtin_route("building_tour");
    const indoor_map::Map m = route_map(r);
    // Each floor's ring (four sides) and the stretch from the start to the turn into the stairwell,
    // on floors 1 and 2 the last side split at that turn and the two stretches in the stairwell,
    // each once however often it is walked.
    std::vector<int> per_floor(3, 0);
    for (const auto& z : m.zones) {
        REQUIRE(z.kind == indoor_map::ZoneKind::altitude);
        ++per_floor[static_cast<size_t>(z.floor)];
        CHECK(z.height_m == doctest::Approx(z.floor * r.floor_height_m).epsilon(1e-3));
        REQUIRE(z.rings.size() == 1);
        CHECK(z.rings[0].size() == 4);
    }
    CHECK(per_floor == std::vector<int>{5, 7, 7});
    // Near a corner of the ring: inside the zones of both sides.
    const indoor_map::Point2 corner{59.5, 29.5};
    int holding = 0;
    for (const auto& z : m.zones) holding += z.floor == 1 && indoor_map::point_in_polygon(corner, z.rings);
    CHECK(holding == 2);
    CHECK(route_map(sim::builtin_route("corridor_loop")).zones.empty());
    CHECK(route_map(sim::builtin_route("stairs")).zones.size() == 3);
}
