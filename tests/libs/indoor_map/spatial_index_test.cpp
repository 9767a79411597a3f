// SPDX-License-Identifier: Apache-2.0
// The wall and zone grids give the answers of a plain loop over every wall
// and zone, on random maps and random segments, and on the cases that break
// grid traversals: segments along cell borders, through cell corners, of zero
// length, outside the grid, and walls longer than a cell.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <pednav_indoor_map/geometry_2d.hpp>
#include <pednav_indoor_map/wall_index.hpp>
#include <pednav_indoor_map/zone_index.hpp>

using namespace pednav::indoor_map;

namespace {

bool brute_crosses(const std::vector<WallSegment>& walls, int floor, Point2 p0, Point2 p1) {
    for (const WallSegment& w : walls)
        if (w.floor == floor && segments_intersect(p0, p1, w.a, w.b)) return true;
    return false;
}

std::vector<WallSegment> random_walls(std::mt19937_64& rng, int count, double size_m) {
    std::uniform_real_distribution<double> pos(0.0, size_m), len(0.1, 12.0), ang(0.0, 2 * M_PI);
    std::uniform_int_distribution<int> floor(-1, 1), axis(0, 2);
    std::vector<WallSegment> walls;
    for (int i = 0; i < count; ++i) {
        const Point2 a{pos(rng), pos(rng)};
        const double l = len(rng);
        const int ax = axis(rng);  // a third on grid-aligned directions
        const double th = ax == 0 ? 0.0 : ax == 1 ? M_PI / 2 : ang(rng);
        walls.push_back({a, {a.e_m + l * std::cos(th), a.n_m + l * std::sin(th)}, floor(rng), i});
    }
    return walls;
}

}  // namespace

TEST_CASE("wall index: the same answers as a loop over every wall, 20 000 random segments") {
    std::mt19937_64 rng(7);
    const std::vector<WallSegment> walls = random_walls(rng, 1500, 100.0);
    for (double cell : {0.5, 2.0, 7.3}) {
        const WallIndex index(walls, cell);
        CHECK(index.wall_count() == 1500);
        std::uniform_real_distribution<double> pos(-10.0, 110.0), step(-3.0, 3.0), far(-60.0, 60.0);
        std::uniform_int_distribution<int> floor(-2, 2);
        int crossings = 0, mismatches = 0;
        for (int i = 0; i < 20000; ++i) {
            const Point2 p0{pos(rng), pos(rng)};
            const bool long_one = i % 10 == 0;
            const Point2 p1{p0.e_m + (long_one ? far(rng) : step(rng)), p0.n_m + (long_one ? far(rng) : step(rng))};
            const int f = floor(rng);
            const bool expected = brute_crosses(walls, f, p0, p1);
            crossings += expected;
            mismatches += index.crosses_wall(f, p0, p1) != expected;
        }
        CAPTURE(cell);
        CHECK(mismatches == 0);
        CHECK(crossings > 2000);  // the test sees both answers often
        CHECK(crossings < 18000);
    }
}

TEST_CASE("wall index: borders, corners, points and the outside of the grid") {
    // Walls on cell borders (cell 1 m, grid from -0.01): x = 2.99 is a border.
    const std::vector<WallSegment> walls = {{{2.99, 0.5}, {2.99, 5.5}, 0, 0},
                                            {{0, 0}, {10, 10}, 0, 1},
                                            {{-5, 8}, {20, 8}, 0, 2},
                                            {{4, 4}, {4, 4}, 1, 3}};
    const WallIndex index(walls, 1.0);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(-8.0, 25.0);
    int mismatches = 0;
    for (int i = 0; i < 20000; ++i) {
        // Endpoints snapped to the grid lines and corners half of the time.
        Point2 p0{pos(rng), pos(rng)}, p1{pos(rng), pos(rng)};
        if (i % 2) {
            p0 = {std::round(p0.e_m) - 0.01, std::round(p0.n_m) - 0.01};
            p1 = {std::round(p1.e_m) - 0.01, std::round(p1.n_m) - 0.01};
        }
        if (i % 7 == 0) p1 = p0;
        for (int f : {0, 1})
            mismatches += index.crosses_wall(f, p0, p1) != brute_crosses(walls, f, p0, p1);
    }
    CHECK(mismatches == 0);
    CHECK(index.crosses_wall(0, {2.5, 3}, {3.5, 3}));          // through the border wall
    CHECK(!index.crosses_wall(0, {2.5, 3}, {2.9, 3}));
    CHECK(index.crosses_wall(0, {-20, 8.5}, {30, 7.5}));       // both ends outside the grid
    CHECK(!index.crosses_wall(0, {-20, 30}, {30, 30}));
    CHECK(index.crosses_wall(1, {3, 3}, {5, 5}));              // a wall of zero length
    CHECK(!index.crosses_wall(2, {0, 10}, {10, 0}));           // a floor without walls
    CHECK_THROWS_AS(WallIndex(walls, 0.0), std::invalid_argument);
}

TEST_CASE("zone index: the same answers as a loop over every zone") {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> pos(0.0, 80.0), size(1.0, 15.0);
    std::vector<Zone> zones;
    for (int i = 0; i < 300; ++i) {
        const double e = pos(rng), n = pos(rng), w = size(rng), h = size(rng);
        Zone z;
        z.kind = static_cast<ZoneKind>(i % 3);
        z.floor = i % 2;
        z.rings = {{{e, n}, {e + w, n + 0.3 * h}, {e + 0.7 * w, n + h}, {e - 0.2 * w, n + 0.6 * h}}};
        if (i % 5 == 0) z.rings.push_back({{e + 0.3 * w, n + 0.3 * h}, {e + 0.5 * w, n + 0.3 * h}, {e + 0.4 * w, n + 0.5 * h}});
        z.height_m = 0;
        z.feature = i;
        zones.push_back(z);
    }
    const ZoneIndex index(zones, 3.0);
    std::uniform_real_distribution<double> q(-10.0, 100.0);
    int mismatches = 0, inside = 0;
    for (int i = 0; i < 20000; ++i) {
        const Point2 p{q(rng), q(rng)};
        const int f = i % 3 - 1;
        const auto kind = static_cast<ZoneKind>(i % 3);
        const Zone* expected = nullptr;
        for (const Zone& z : zones)
            if (z.floor == f && z.kind == kind && point_in_polygon(p, z.rings)) {
                expected = &z;
                break;
            }
        const Zone* got = index.zone_at(f, p, kind);
        mismatches += (got == nullptr) != (expected == nullptr) || (got && got->feature != expected->feature);
        inside += expected != nullptr;
    }
    CHECK(mismatches == 0);
    CHECK(inside > 1000);
    CHECK(index.has_kind(0, ZoneKind::walkable));
    CHECK(!index.has_kind(5, ZoneKind::walkable));
}

TEST_CASE("wall index: the first wall a segment meets, as a loop over every wall finds it") {
    std::mt19937_64 rng(17);
    const std::vector<WallSegment> walls = random_walls(rng, 800, 60.0);
    const WallIndex index(walls, 2.0);
    std::uniform_real_distribution<double> pos(-5.0, 65.0), step(-8.0, 8.0);
    int mismatches = 0, hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Point2 p0{pos(rng), pos(rng)}, p1{p0.e_m + step(rng), p0.n_m + step(rng)};
        const int f = i % 3 - 1;
        // The loop: the smallest parameter along [p0, p1] where a wall meets it.
        double best = INFINITY;
        for (const WallSegment& w : walls) {
            if (w.floor != f || !segments_intersect(p0, p1, w.a, w.b)) continue;
            const double rx = p1.e_m - p0.e_m, ry = p1.n_m - p0.n_m, sx = w.b.e_m - w.a.e_m, sy = w.b.n_m - w.a.n_m;
            const double den = rx * sy - ry * sx;
            if (den == 0.0) continue;  // collinear: random walls almost never are
            best = std::min(best, std::clamp(((w.a.e_m - p0.e_m) * sy - (w.a.n_m - p0.n_m) * sx) / den, 0.0, 1.0));
        }
        double t = -1;
        Point2 a{}, b{};
        const bool hit = index.first_crossing(f, p0, p1, &t, &a, &b);
        hits += hit;
        if (hit != std::isfinite(best) || (hit && std::abs(t - best) > 1e-9)) ++mismatches;
        if (hit) {
            // The wall returned is one the segment meets at t.
            const Point2 at{p0.e_m + t * (p1.e_m - p0.e_m), p0.n_m + t * (p1.n_m - p0.n_m)};
            if (distance_to_segment(at, a, b) > 1e-6) ++mismatches;
        }
    }
    CHECK(mismatches == 0);
    CHECK(hits > 3000);
}

TEST_CASE("a wall or zone a thousand kilometres wide gets coarser cells and the same answers") {
    // Found by fuzz_map_geojson: one mistyped longitude (7.85 for 8.85) put a
    // wall 67 km away and the 2 m grid over that extent took seconds to build;
    // a degree wider, billions of cells.
    const std::vector<WallSegment> walls{{{-500000.0, 0.0}, {500000.0, 3.0}, 0, 0},
                                         {{0.0, -5.0}, {0.0, 400000.0}, 0, 1},
                                         {{1.0, 1.0}, {3.0, 1.0}, 1, 2}};
    const WallIndex index(walls, 2.0);
    CHECK(index.cell_m() > 2.0);
    CHECK(index.cell_m() < 2.0 * 4096);
    const Point2 queries[][2] = {{{10.0, -1.0}, {10.0, 1.0}}, {{10.0, 5.0}, {12.0, 7.0}},      {{-1.0, 100.0}, {1.0, 100.0}},
                                 {{2.0, 0.0}, {2.0, 2.0}},    {{2.0, 1.5}, {2.5, 1.5}},        {{-9e5, -9e5}, {9e5, 9e5}}};
    for (int floor = 0; floor < 2; ++floor)
        for (const auto& q : queries) CHECK(index.crosses_wall(floor, q[0], q[1]) == brute_crosses(walls, floor, q[0], q[1]));
    // A small building's walls keep the cell asked for.
    const std::vector<WallSegment> room{{{0.0, 0.0}, {30.0, 0.0}, 0, 0}, {{30.0, 0.0}, {30.0, 20.0}, 0, 1}};
    CHECK(WallIndex(room, 2.0).cell_m() == 2.0);

    Zone wide{ZoneKind::walkable, 0, {{{-400000.0, -1.0}, {400000.0, -1.0}, {400000.0, 300000.0}}}, NAN, 0};
    const ZoneIndex zones({wide}, 2.0);
    CHECK(zones.cell_m() > 2.0);
    CHECK(zones.in_zone(0, {0.0, 0.0}, ZoneKind::walkable));
    CHECK_FALSE(zones.in_zone(0, {0.0, 200000.0}, ZoneKind::walkable));
    CHECK(ZoneIndex({Zone{ZoneKind::walkable, 0, {{{0.0, 0.0}, {30.0, 0.0}, {30.0, 20.0}}}, NAN, 0}}, 2.0).cell_m() == 2.0);
}
