// SPDX-License-Identifier: Apache-2.0
// A walk to simulate: where the walker goes, how fast, and what surrounds it.
//
// Routes are JSON documents ("pednav-route/1", see docs/simulator.md) or one of
// the built-in routes. Positions are metres in the ENU frame of the route's
// origin; the walk starts at the first waypoint.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pednav::sim {

// Waypoint i > 0 also describes the segment that leads to it from waypoint i-1.
struct Waypoint {
    double enu_m[3] = {0.0, 0.0, 0.0};
    bool stairs = false;   // segment i-1 -> i is a flight of stairs (default: true when the height changes)
    bool outdoor = false;  // segment i-1 -> i is outdoors: GNSS fixes are available on it
    double still_s = 0.0;  // the walker stands still this long on arrival
};

// A local magnetic disturbance (steel, machinery): `field_ut` (ENU) is added to
// the Earth field at the centre, fading smoothly to nothing at `radius_m`.
struct MagDisturbance {
    double center_enu_m[3] = {0.0, 0.0, 0.0};
    double radius_m = 1.0;
    double field_ut[3] = {0.0, 0.0, 0.0};
};

// One wall of the route's building as a polyline on a floor (for maps and plots).
struct Wall {
    int floor = 0;
    std::vector<std::array<double, 2>> points_enu_m;
};

struct Route {
    std::string name;
    std::string description;
    std::vector<Waypoint> waypoints;    // at least two
    double speed_mps = 1.3;             // walking speed on level floors
    double step_length_m = 0.7;         // one step (half a stride) on level floors
    double stance_fraction = 0.28;      // share of a stride the foot is flat and still
    double stair_rise_m = 0.17;         // per stair step
    double stair_run_m = 0.28;          // per stair step (horizontal)
    double stairs_step_period_s = 0.6;  // one step on stairs (one stair per step)
    double floor_height_m = 3.4;        // floor index = round(height / floor_height)
    double start_still_s = 10.0;        // standing still before the first step (alignment)
    double end_still_s = 5.0;           // standing still after the last step
    double origin_lat_deg = 48.8566;    // WGS-84 position of the ENU origin
    double origin_lon_deg = 2.3522;
    double origin_height_m = 50.0;  // ellipsoidal height of the ENU origin
    std::vector<MagDisturbance> mag_disturbances;
    std::vector<Wall> walls;
};

// Parses a route document; throws std::runtime_error naming the bad key
// (as a JSON pointer, e.g. "/waypoints/3/enu_m").
Route parse_route(const nlohmann::json& j);
// The inverse of parse_route (round trip).
nlohmann::json route_to_json(const Route& route);

// "corridor_loop", "stairs", "figure_eight", "building_tour", "outdoor_indoor";
// throws std::runtime_error for an unknown name.
Route builtin_route(const std::string& name);
std::vector<std::string> builtin_route_names();

// Horizontal length of the route's polyline (what a walker covers).
double route_length_m(const Route& route);

}  // namespace pednav::sim
