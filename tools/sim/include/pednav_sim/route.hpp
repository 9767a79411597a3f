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

// GNSS reception along a segment: whether there are fixes, how large the
// receiver's errors are against SimOptions' (which are "good"), and what the
// records say of the solution.
struct GnssQuality {
    std::string name = "good";  // "good", "degraded", "none", or "custom" (given as an object)
    bool fixes = true;          // false: no fix at all (a tunnel, a covered passage)
    double error_scale = 1.0;   // multiplies every GNSS error sigma and the accuracy the fixes report
    int satellites = 12;        // pn_gnss_t.satellites
};

// The presets: "good" (open sky: scale 1, 12 satellites), "degraded" (beside
// tall buildings: scale 4, 6 satellites), "none"; throws for another name.
GnssQuality gnss_quality_preset(const std::string& name);

// Waypoint i > 0 also describes the segment that leads to it from waypoint i-1.
struct Waypoint {
    double enu_m[3] = {0.0, 0.0, 0.0};
    bool stairs = false;   // segment i-1 -> i is a flight of stairs (default: true when the height changes)
    bool outdoor = false;  // segment i-1 -> i is outdoors: GNSS fixes are available on it
    double still_s = 0.0;  // the walker stands still this long on arrival
    // GNSS on segment i-1 -> i when given; otherwise "good" outdoors, "none" indoors.
    bool gnss_given = false;
    GnssQuality gnss;
};

// Multipath: from t_s for duration_s every fix is off by offset_enu_m (the
// accuracy it reports does not change: the receiver does not know).
struct GnssJump {
    double t_s = 0.0;
    double duration_s = 0.0;
    double offset_enu_m[3] = {0.0, 0.0, 0.0};
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
    double speed_mps = 1.3;             // walking speed on level floors at the nominal step; a level
                                        // stride s times the nominal walks at speed_mps s^2 (walk ratio)
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
    std::vector<GnssJump> gnss_jumps;
};

// The GNSS quality on segment `segment` (into waypoint segment + 1).
const GnssQuality& segment_gnss(const Route& route, size_t segment);

// Parses a route document; throws std::runtime_error naming the bad key
// (as a JSON pointer, e.g. "/waypoints/3/enu_m").
Route parse_route(const nlohmann::json& j);
// The inverse of parse_route (round trip).
nlohmann::json route_to_json(const Route& route);

// "corridor_loop", "stairs", "figure_eight", "building_tour", "outdoor_indoor", "gnss_outage";
// throws std::runtime_error for an unknown name.
Route builtin_route(const std::string& name);
std::vector<std::string> builtin_route_names();

// Horizontal length of the route's polyline (what a walker covers).
double route_length_m(const Route& route);

}  // namespace pednav::sim
