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

// biba-chest-xsens/<route>.txt through `preset_path` with the map matcher
// on map/ converted by rairyuu_to_geojson ((0, 0) at core.txt's start point),
// started there with heading_deg. No landmarks: crossings and particles only.
MatchedRecordingScore run_biba_route(const std::string& data_dir, const std::string& route,
                                     const std::string& preset_path, double heading_deg,
                                     const std::string& plugin_dir, const std::string& work_dir);

}  // namespace pednav::test
