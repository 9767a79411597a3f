// SPDX-License-Identifier: Apache-2.0
// A config calibrated the way pednav calibrate does it, on walks of the walk
// list: simulated walks (their distance) or humolire walks (their timed
// landmarks). How the suite and the tests score a calibrated pipeline on walks
// it was not calibrated on.
#pragma once

#include <string>
#include <vector>

#include <pednav_eval/calibration.hpp>
#include <pednav_eval/walks.hpp>

namespace pednav::chest_eval {

struct Calibrated {
    std::string config_json;  // the config with the fitted constants
    std::string summary;      // what was fitted (eval::CalibrationResult::summary)
};

// Runs the walks through config_json and fits its position filter
// (pipelines/<mount>/position_filter). Throws std::runtime_error when a walk
// fails or the fit is impossible.
Calibrated calibrate_on_sims(const std::string& config_json, const std::string& mount,
                             const std::vector<eval::SimulatedWalk>& walks, const std::vector<std::string>& plugin_dirs,
                             const eval::CalibrationOptions& options = {});
Calibrated calibrate_on_recordings(const std::string& config_json, const std::string& mount,
                                   const std::vector<eval::RecordedWalk>& walks,
                                   const std::vector<std::string>& plugin_dirs,
                                   const eval::CalibrationOptions& options = {});

}  // namespace pednav::chest_eval

namespace pednav::chest_eval {

// The params of the config's pipelines/<mount>/position_filter with every
// key its plugin's schema declares and the config leaves out set to the
// schema's default (from pn_plugins_describe over plugin_dirs), so that a
// config listing only what it changes can be calibrated. Throws
// std::runtime_error when the stage or its plugin is not found.
nlohmann::json position_filter_params(const nlohmann::json& config, const std::string& mount,
                                      const std::vector<std::string>& plugin_dirs);

}  // namespace pednav::chest_eval
