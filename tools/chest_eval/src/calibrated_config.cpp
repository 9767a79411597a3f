// SPDX-License-Identifier: Apache-2.0
#include <pednav_chest_eval/calibrated_config.hpp>

#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav/pn_engine.h>
#include <pednav_engine/replay.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::chest_eval {

namespace {

Calibrated fitted(const std::string& config_json, const std::string& mount,
                  const std::vector<eval::CalibrationRun>& runs, const eval::CalibrationOptions& options,
                  const std::vector<std::string>& plugin_dirs) {
    nlohmann::json doc = nlohmann::json::parse(config_json);
    const nlohmann::json::json_pointer where("/pipelines/" + mount + "/position_filter/params");
    const eval::CalibrationResult r =
        eval::calibrate_position_filter(position_filter_params(doc, mount, plugin_dirs), runs, options);
    for (const auto& [key, value] : r.params.items()) doc[where][key] = value;
    return {doc.dump(), r.summary};
}

}  // namespace

nlohmann::json position_filter_params(const nlohmann::json& config, const std::string& mount,
                                      const std::vector<std::string>& plugin_dirs) {
    const nlohmann::json::json_pointer stage("/pipelines/" + mount + "/position_filter");
    if (!config.contains(stage) || !config.at(stage).is_object())
        throw std::runtime_error("the config has no " + stage.to_string());
    const nlohmann::json& st = config.at(stage);
    const std::string id = st.value("plugin", std::string());
    nlohmann::json params = st.contains("params") && st.at("params").is_object() ? st.at("params") : nlohmann::json::object();
    std::vector<const char*> dirs;
    for (const std::string& d : plugin_dirs) dirs.push_back(d.c_str());
    size_t size = 0;
    pn_error_t err{};
    err.struct_size = sizeof err;
    pn_plugins_describe(dirs.data(), static_cast<uint32_t>(dirs.size()), 0, nullptr, 0, &size, nullptr);
    std::string text(size, '\0');
    if (PN_FAILED(pn_plugins_describe(dirs.data(), static_cast<uint32_t>(dirs.size()), 0, text.data(), size, &size, &err)))
        throw std::runtime_error(std::string("listing the plugins: ") + err.message);
    text.resize(size ? size - 1 : 0);
    const nlohmann::json listing = nlohmann::json::parse(text);
    for (const nlohmann::json& p : listing.value("plugins", nlohmann::json::array())) {
        if (p.value("id", std::string()) != id) continue;
        const nlohmann::json schema = p.value("params_schema", nlohmann::json::object());
        const nlohmann::json properties = schema.value("properties", nlohmann::json::object());
        for (const auto& [key, spec] : properties.items())
            if (!params.contains(key) && spec.contains("default")) params[key] = spec["default"];
        return params;
    }
    throw std::runtime_error("no plugin " + id + " (the position filter) in the plugin directories");
}

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
    return fitted(config_json, mount, runs, options, plugin_dirs);
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
    return fitted(config_json, mount, runs, options, plugin_dirs);
}

}  // namespace pednav::chest_eval
