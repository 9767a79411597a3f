// SPDX-License-Identifier: Apache-2.0
// A shared recording with landmarks through a pipeline with and without the
// map matcher, on the recording's converted map: the error at each landmark
// time from the given start point and heading, and the wall crossings of the
// output track. For the humolire-phone walks (handheld or chest preset) and,
// without landmarks, the biba-chest-xsens routes (crossings and live
// particles only).
#pragma once

#include <string>
#include <vector>

#include <pednav_eval/metrics.hpp>

namespace pednav::test {

struct MatchedRecordingScore {
    eval::ErrorStats with_map, without_map;  // horizontal error at the landmark times, m
    int crossings = 0;                       // of the matched output track, on the map
    uint32_t recoveries = 0, min_live = 0;
    size_t positions = 0;
};

// humolire-phone/<walk> through `preset_path` (configs/handheld.json or
// chest.json) with the map matcher stage, on maps/map_data.json converted
// with pednav.map/1's converter (HuMoLiRe's metres, the keypoints' frame).
MatchedRecordingScore run_humolire_walk(const std::string& data_dir, const std::string& walk,
                                        const std::string& preset_path, const std::string& plugin_dir,
                                        const std::string& work_dir);

}  // namespace pednav::test

namespace pednav::test {

// How a biba-chest-xsens route is run: map/ converted by rairyuu_to_geojson
// at `scale_m_per_px` ((0, 0) at core.txt's start point), the route started
// at `start_enu_m` with `heading_deg`.
struct BibaRun {
    std::string route;  // "rita_to_kar" or "kar_to_rita"
    double scale_m_per_px = 0.0;
    double start_enu_m[2] = {0.0, 0.0};
    double heading_deg = 0.0;
};

struct BibaScore {
    MatchedRecordingScore matched;     // no landmarks: crossings and particles only
    double end_enu_m[2] = {0.0, 0.0};  // the last output
    double distance_m = 0.0;           // along the output track
};

BibaScore run_biba_route(const std::string& data_dir, const BibaRun& run, const std::string& preset_path,
                         const std::string& plugin_dir, const std::string& work_dir);

}  // namespace pednav::test
