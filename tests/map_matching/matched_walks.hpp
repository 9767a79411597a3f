// SPDX-License-Identifier: Apache-2.0
// A simulated multi-floor walk through a pipeline with the map matcher and
// the walk's building map (the simulator's building.geojson), through the
// real engine and loader, scored against the simulator's truth.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_types.h>
#include <pednav_engine/replay.hpp>
#include <pednav_eval/walks.hpp>
#include <pednav_indoor_map/map.hpp>

namespace pednav::test {

struct MatchedWalkScore {
    size_t positions = 0;
    double floor_right = 0;    // share of the outputs on the truth's floor
    double ipin_p75_m = 0;     // p75 of horizontal error + 15 m per floor wrong
    double horizontal_p75_m = 0, horizontal_max_m = 0;
    double raw_p75_m = 0;      // the track without the map matcher, horizontal p75
    int crossings = 0;         // output segments on one floor that cross a wall of it
    uint32_t recoveries = 0;
    uint32_t min_live = 0;     // fewest live particles of any output
    size_t recovered_flags = 0;
    std::string describe_json;
    std::vector<pn_position_t> track;
};

struct MatchedWalk {
    eval::SimulatedWalk walk;
    nlohmann::json matcher_params = nlohmann::json::object();
    double start_offset_m[2] = {0, 0};  // the start point given to the engine, off the truth's
    std::string config_path;            // the mount's preset
    std::string plugin_dir;
    std::string work_dir;               // where the map file is written
    std::string map_document;           // the map; empty = the simulator's building.geojson of the route
};

// The walk's building.geojson (pednav::sim::building_map) and its model.
std::string walk_map_document(const eval::SimulatedWalk& walk);
indoor_map::Map walk_map(const eval::SimulatedWalk& walk);
MatchedWalkScore run_matched_walk(const MatchedWalk& w);

}  // namespace pednav::test
