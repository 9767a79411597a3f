// SPDX-License-Identifier: Apache-2.0
#include <pednav_chest_eval/calibrated_config.hpp>

#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_engine/replay.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::chest_eval {

namespace {

Calibrated fitted(const std::string& config_json, const std::string& mount,
                  const std::vector<eval::CalibrationRun>& runs, const eval::CalibrationOptions& options) {
    nlohmann::json doc = nlohmann::json::parse(config_json);
    const nlohmann::json::json_pointer where("/pipelines/" + mount + "/position_filter/params");
    if (!doc.contains(where)) throw std::runtime_error("the config has no " + where.to_string());
    const eval::CalibrationResult r = eval::calibrate_position_filter(doc.at(where), runs, options);
    for (const auto& [key, value] : r.params.items()) doc[where][key] = value;
    return {doc.dump(), r.summary};
}

}  // namespace

Calibrated calibrate_on_sims(const std::string& config_json, const std::string& mount,
                             const std::vector<eval::SimulatedWalk>& walks, const std::vector<std::string>& plugin_dirs,
                             const eval::CalibrationOptions& options) {
    std::vector<eval::CalibrationRun> runs;
    for (const eval::SimulatedWalk& w : walks) {
        const sim::SimOutput out = sim::simulate(eval::sim_route(w), eval::sim_options(w));
        auto doc = nlohmann::json::parse(config_json);
        doc["imu_rate_hz"] = w.rate_hz;
        ReplayOptions o;
        o.config_json = doc.dump();
        o.plugin_dirs = plugin_dirs;
        o.heading_deg = out.truth.front().heading_deg;
        const ReplayResult r = replay(o, out.records());
        if (!r.error.empty()) throw std::runtime_error("sim " + w.route + ": " + r.error);
        runs.push_back({"sim " + w.route, r.strides, r.steps, {eval::whole_walk_leg(out.distance_m)}});
    }
    return fitted(config_json, mount, runs, options);
}

Calibrated calibrate_on_recordings(const std::string& config_json, const std::string& mount,
                                   const std::vector<eval::RecordedWalk>& walks,
                                   const std::vector<std::string>& plugin_dirs,
                                   const eval::CalibrationOptions& options) {
    std::vector<eval::CalibrationRun> runs;
    for (const eval::RecordedWalk& w : walks) {
        ReplayOptions o;
        o.config_json = config_json;
        o.plugin_dirs = plugin_dirs;
        const ReplayResult r = replay(o, io::merged_records(io::read_sensor_file(w.input)));
        if (!r.error.empty()) throw std::runtime_error(w.name + ": " + r.error);
        runs.push_back({w.name, r.strides, r.steps, eval::landmark_legs(w.truth_path)});
    }
    return fitted(config_json, mount, runs, options);
}

}  // namespace pednav::chest_eval
