// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <pednav_indoor_map/geometry_2d.hpp>

using namespace pednav::indoor_map;

TEST_CASE("geometry: segment intersection, crossing, touching, apart") {
    CHECK(segments_intersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));
    CHECK(segments_intersect({0, 0}, {1, 0}, {1, 0}, {1, 5}));   // touching at an end
    CHECK(segments_intersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));   // collinear overlap
    CHECK(!segments_intersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));  // collinear apart
    CHECK(!segments_intersect({0, 0}, {1, 1}, {0, 1}, {0.4, 0.6}));
    CHECK(orientation({0, 0}, {1, 0}, {0, 1}) == doctest::Approx(1.0));
}

TEST_CASE("geometry: points in rings and polygons with holes, distances") {
    const std::vector<Point2> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    const std::vector<Point2> hole = {{4, 4}, {6, 4}, {6, 6}, {4, 6}};
    CHECK(point_in_ring({5, 5}, square));
    CHECK(!point_in_ring({11, 5}, square));
    CHECK(point_in_polygon({2, 2}, {square, hole}));
    CHECK(!point_in_polygon({5, 5}, {square, hole}));
    CHECK(!point_in_polygon({5, 5}, {}));
    CHECK(distance_to_segment({5, 3}, {0, 0}, {10, 0}) == doctest::Approx(3.0));
    CHECK(distance_to_segment({-3, 4}, {0, 0}, {10, 0}) == doctest::Approx(5.0));
    CHECK(distance_to_polyline({12, 5}, square) == doctest::Approx(2.0));
    CHECK(distance_to_polyline({3, 4}, {{0, 0}}) == doctest::Approx(5.0));
}

TEST_CASE("geometry: a self-crossing ring is found, with its edges") {
    const std::vector<Point2> bow_tie = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};
    int a = -1, b = -1;
    CHECK(ring_self_intersects(bow_tie, &a, &b));
    CHECK(a == 0);
    CHECK(b == 2);
    CHECK(!ring_self_intersects({{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
    CHECK(!ring_self_intersects({{0, 0}, {1, 0}, {0, 1}}));
}
