// SPDX-License-Identifier: Apache-2.0
// The built-in walks used by the tests, the accuracy report and the README demo.
#include <cmath>
#include <stdexcept>

#include <pednav_sim/route.hpp>

namespace pednav::sim {

namespace {

Waypoint wp(double x, double y, double z = 0.0, bool outdoor = false, double still_s = 0.0) {
    Waypoint w;
    w.enu_m[0] = x;
    w.enu_m[1] = y;
    w.enu_m[2] = z;
    w.outdoor = outdoor;
    w.still_s = still_s;
    return w;
}

// Builds the waypoint list: stairs wherever the height changes.
void finish(Route& r) {
    for (size_t i = 1; i < r.waypoints.size(); ++i)
        r.waypoints[i].stairs = std::fabs(r.waypoints[i].enu_m[2] - r.waypoints[i - 1].enu_m[2]) > 1e-6;
}

Wall rect(int floor, double x0, double y0, double x1, double y1) {
    return {floor, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}, {x0, y0}}};
}

// Rectangular ring corridor of width w around the rectangle (x0,y0)-(x1,y1).
void ring_walls(Route& r, int floor, double x0, double y0, double x1, double y1, double w) {
    r.walls.push_back(rect(floor, x0 - w / 2, y0 - w / 2, x1 + w / 2, y1 + w / 2));
    r.walls.push_back(rect(floor, x0 + w / 2, y0 + w / 2, x1 - w / 2, y1 - w / 2));
}

Route corridor_loop() {
    Route r;
    r.name = "corridor_loop";
    r.description =
        "One lap of a closed 40 m x 20 m rectangular corridor (120 m = 3 x 40 m), "
        "four 90-degree left turns, ground floor, ends where it starts";
    r.waypoints = {wp(0, 0), wp(40, 0), wp(40, 20), wp(0, 20), wp(0, 0)};
    ring_walls(r, 0, 0, 0, 40, 20, 2.0);
    finish(r);
    return r;
}

Route stairs() {
    Route r;
    r.name = "stairs";
    r.description =
        "10 m corridor, two flights of 10 stairs up (U-shaped stairwell, 1.5 m landing) to floor 1, "
        "a 23 m loop on floor 1, the same two flights down, back to the start";
    const double h1 = 10 * r.stair_rise_m, run = 10 * r.stair_run_m;  // one flight
    r.waypoints = {wp(0, 0),
                   wp(10, 0),
                   wp(10 + run, 0, h1),
                   wp(10 + run, 1.5, h1),
                   wp(10, 1.5, 2 * h1),
                   wp(0, 1.5, 2 * h1),
                   wp(0, 3.0, 2 * h1),
                   wp(10, 3.0, 2 * h1),
                   wp(10, 1.5, 2 * h1),
                   wp(10 + run, 1.5, h1),
                   wp(10 + run, 0, h1),
                   wp(10, 0),
                   wp(0, 0)};
    r.floor_height_m = 2 * h1;
    r.walls.push_back({0, {{-1, -1}, {10 + run + 1, -1}, {10 + run + 1, 2.5}, {10, 2.5}}});
    r.walls.push_back({0, {{-1, -1}, {-1, 1}, {10, 1}}});
    r.walls.push_back({1,
                       {{-1, 0.5},
                        {-1, 4},
                        {11, 4},
                        {11, 2.5},
                        {10 + run + 1, 2.5},
                        {10 + run + 1, -1},
                        {10, -1},
                        {10, 0.5},
                        {-1, 0.5}}});
    r.walls.push_back(rect(1, 1, 2.0, 9, 2.5));
    finish(r);
    return r;
}

Route figure_eight() {
    Route r;
    r.name = "figure_eight";
    r.description =
        "Two laps of a figure eight in an open hall: two 6 m-radius circles (24-gons) touching at the "
        "start, left loop counter-clockwise, right loop clockwise; a steel pillar disturbs the compass";
    const int n = 24;
    const double R = 6.0;
    r.waypoints.push_back(wp(0, 0));
    for (int lap = 0; lap < 2; ++lap) {
        // Upper circle centred at (0, R), counter-clockwise from its bottom; lower one centred at (0, -R),
        // clockwise from its top: both leave the start heading east.
        for (int k = 1; k <= n; ++k) {
            const double a = -M_PI / 2 + 2 * M_PI * k / n;
            r.waypoints.push_back(wp(R * std::cos(a), R + R * std::sin(a)));
        }
        for (int k = 1; k <= n; ++k) {
            const double a = M_PI / 2 - 2 * M_PI * k / n;
            r.waypoints.push_back(wp(R * std::cos(a), -R + R * std::sin(a)));
        }
    }
    r.walls.push_back(rect(0, -12, -16, 12, 16));
    r.walls.push_back(rect(0, 7.6, -0.4, 8.4, 0.4));  // pillar
    r.mag_disturbances.push_back({{8.0, 0.0, 1.0}, 3.0, {15.0, -10.0, 8.0}});
    finish(r);
    return r;
}

Route building_tour() {
    Route r;
    r.name = "building_tour";
    r.description =
        "Long tour of a three-storey office building: the 60 m x 30 m ring corridor of the ground floor, "
        "four flights up a U-shaped stairwell to the second floor and its ring, two flights down to the "
        "first floor and its ring, two flights down and back to the start; stops at doors, magnetic "
        "disturbances at the lift shaft and radiators";
    const double h1 = 10 * r.stair_rise_m, run = 10 * r.stair_run_m, H = 2 * h1;
    r.floor_height_m = H;
    auto& w = r.waypoints;
    auto ring = [&](double z, double stop_s) {  // from (8 or 0, 0) around the ring back to (0, 0)
        w.push_back(wp(60, 0, z));
        w.push_back(wp(60, 30, z, false, stop_s));
        w.push_back(wp(0, 30, z));
        w.push_back(wp(0, 0, z));
    };
    // Stairwell south of the corridor: the east-going flight starts at (10, -1.5), the
    // west-going one ends at (10, -3); floors are reached at (10, -3) and left via (8, -3).
    auto up = [&](int floor) {  // from (10, -1.5, floor H) to (10, -3, (floor + 1) H)
        w.push_back(wp(10 + run, -1.5, floor * H + h1));
        w.push_back(wp(10 + run, -3.0, floor * H + h1));
        w.push_back(wp(10, -3.0, (floor + 1) * H));
    };
    auto down = [&](int floor) {  // from (10, -3, floor H) to (10, -1.5, (floor - 1) H)
        w.push_back(wp(10 + run, -3.0, (floor - 1) * H + h1));
        w.push_back(wp(10 + run, -1.5, (floor - 1) * H + h1));
        w.push_back(wp(10, -1.5, (floor - 1) * H));
    };
    w.push_back(wp(0, 0));
    ring(0.0, 3.0);
    w.push_back(wp(10, 0));
    w.push_back(wp(10, -1.5));
    up(0);
    w.push_back(wp(10, -1.5, H));
    up(1);
    w.push_back(wp(8, -3.0, 2 * H));
    w.push_back(wp(8, 0, 2 * H));
    ring(2 * H, 5.0);
    w.push_back(wp(8, 0, 2 * H));
    w.push_back(wp(8, -3.0, 2 * H));
    w.push_back(wp(10, -3.0, 2 * H));
    down(2);
    w.push_back(wp(10, -3.0, H));
    w.push_back(wp(8, -3.0, H));
    w.push_back(wp(8, 0, H));
    ring(H, 2.0);
    w.push_back(wp(8, 0, H));
    w.push_back(wp(8, -3.0, H));
    w.push_back(wp(10, -3.0, H));
    down(1);
    w.push_back(wp(10, 0));
    w.push_back(wp(0, 0));
    for (int f = 0; f < 3; ++f) {
        ring_walls(r, f, 0, 0, 60, 30, 2.5);
        r.walls.push_back(rect(f, 7, -3.75, 10 + run + 0.5, -0.75));  // stairwell
    }
    r.mag_disturbances.push_back({{30.0, 0.0, 1.0}, 2.5, {-20.0, 12.0, -10.0}});
    r.mag_disturbances.push_back({{60.0, 15.0, 0.5}, 1.5, {10.0, 10.0, 5.0}});
    r.mag_disturbances.push_back({{30.0, 30.0, H + 0.5}, 1.5, {-8.0, 15.0, 5.0}});
    r.mag_disturbances.push_back({{45.0, 0.0, 2 * H + 0.5}, 2.0, {12.0, -6.0, -4.0}});
    finish(r);
    return r;
}

Route outdoor_indoor() {
    Route r;
    r.name = "outdoor_indoor";
    r.description =
        "Outdoors 50 m to a building (GNSS), 80 m through its corridors (no GNSS), out and 70 m back "
        "outdoors to the start";
    r.start_still_s = 20.0;
    r.waypoints = {wp(0, 0),   wp(50, 0, 0, true), wp(80, 0),        wp(80, 20),
                   wp(50, 20), wp(0, 20, 0, true), wp(0, 0, 0, true)};
    // Building from x = 50 to 82: a ring corridor with doors at (50, 0) and (50, 20).
    r.walls.push_back({0, {{50, -1.5}, {82, -1.5}, {82, 21.5}, {50, 21.5}}});
    r.walls.push_back(rect(0, 50, 1.5, 78, 18.5));
    finish(r);
    return r;
}

// A 440 m walk around a city block, all outdoors, for the GNSS pipelines:
// open sky, beside tall buildings, a 60 s outage (78 m at 1.3 m/s under a
// covered passage, with a turn), beside buildings again, open sky.
Route gnss_outage() {
    Route r;
    r.name = "gnss_outage";
    r.description =
        "440 m around a city block, all outdoors: 120 m open sky, 60 m beside tall buildings (degraded), "
        "a 60 s GNSS outage over 78 m with a turn, 82 m degraded, 100 m open sky back to the start";
    r.start_still_s = 20.0;
    auto seg = [](double x, double y, const char* quality) {
        Waypoint w = wp(x, y, 0, true);
        w.gnss = gnss_quality_preset(quality);
        w.gnss_given = true;
        return w;
    };
    r.waypoints = {wp(0, 0, 0, true),          seg(120, 0, "good"),      seg(120, 60, "degraded"),
                   seg(120, 100, "none"),      seg(82, 100, "none"),     seg(0, 100, "degraded"),
                   seg(0, 0, "good")};
    finish(r);
    return r;
}

}  // namespace

std::vector<std::string> builtin_route_names() {
    return {"corridor_loop", "stairs", "figure_eight", "building_tour", "outdoor_indoor", "gnss_outage"};
}

Route builtin_route(const std::string& name) {
    if (name == "corridor_loop") return corridor_loop();
    if (name == "stairs") return stairs();
    if (name == "figure_eight") return figure_eight();
    if (name == "building_tour") return building_tour();
    if (name == "outdoor_indoor") return outdoor_indoor();
    if (name == "gnss_outage") return gnss_outage();
    throw std::runtime_error("sim: unknown built-in route '" + name + "'");
}

}  // namespace pednav::sim
