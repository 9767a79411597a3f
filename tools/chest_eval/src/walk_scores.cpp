// SPDX-License-Identifier: Apache-2.0
#include <pednav_chest_eval/walk_scores.hpp>

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/track.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::chest_eval {

namespace {

// The run's outputs scored against the truth (the report's alignment: none
// for a walk started at its known start, the start point for a simulated one).
WalkScore score(const ReplayResult& r, const eval::Truth& truth, eval::Alignment alignment) {
    if (r.positions.empty()) throw std::runtime_error("no positions");
    WalkScore s;
    eval::Track track = eval::track_from_positions(r.positions);
    track.step_times_s = eval::step_times_from_steps(r.steps);
    track.has_steps = true;
    eval::EvalOptions eo;
    eo.alignment = alignment;
    s.metrics = eval::evaluate(track, truth, eo);
    s.steps = walking_steps(r.steps);
    for (const pn_stride_t& st : r.strides) s.distance_m += st.length_m;
    s.mag_used_pct = mag_used_pct(r.attitudes);
    const pn_position_t &a = r.positions.front(), &b = r.positions.back();
    s.closure_m = std::hypot(b.pos_enu_m[0] - a.pos_enu_m[0], b.pos_enu_m[1] - a.pos_enu_m[1]);
    return s;
}

}  // namespace

size_t walking_steps(const std::vector<pn_step_t>& steps) {
    size_t n = 0;
    for (const pn_step_t& s : steps) n += s.motion_mode != PN_STEP_MODE_STATIC;
    return n;
}

double mag_used_pct(const std::vector<pn_attitude_t>& attitudes) {
    if (attitudes.empty()) return 0.0;
    size_t n = 0;
    for (const pn_attitude_t& a : attitudes) n += (a.header.flags & PN_ATTITUDE_FLAG_MAG_USED) != 0;
    return 100.0 * static_cast<double>(n) / static_cast<double>(attitudes.size());
}

ReplayResult run_recording(const std::string& path, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs) {
    if (!std::filesystem::exists(path)) throw std::runtime_error("missing recording " + path);
    const io::SensorLog log = io::read_sensor_file(path);
    ReplayOptions o;
    o.config_json = config_json;
    o.plugin_dirs = plugin_dirs;
    o.keep_attitudes = true;
    ReplayResult r = replay(o, io::merged_records(log));
    if (!r.error.empty()) throw std::runtime_error(path + ": " + r.error);
    return r;
}

WalkScore score_recorded(const eval::RecordedWalk& walk, const std::string& config_json,
                         const std::vector<std::string>& plugin_dirs) {
    if (!std::filesystem::exists(walk.input)) throw std::runtime_error(walk.name + ": missing recording " + walk.input);
    const eval::Truth truth = eval::read_walk_truth(walk);
    const io::SensorLog log = io::read_sensor_file(walk.input);
    ReplayOptions o;
    o.config_json = eval::with_user_height(config_json, walk.user_height_m);
    o.plugin_dirs = plugin_dirs;
    o.keep_attitudes = true;
    if (walk.give_start) {
        o.start_enu_m[0] = truth.start_x_m;
        o.start_enu_m[1] = truth.start_y_m;
        o.heading_deg = truth.start_heading_deg;
    }
    const ReplayResult r = replay(o, io::merged_records(log));
    if (!r.error.empty()) throw std::runtime_error(walk.name + ": " + r.error);
    return score(r, truth, walk.alignment);
}

WalkScore score_sim(const eval::SimulatedWalk& walk, const std::string& config_json,
                    const std::vector<std::string>& plugin_dirs) {
    const sim::Route route = eval::sim_route(walk);
    const sim::SimOutput out = sim::simulate(route, eval::sim_options(walk));
    auto doc = nlohmann::json::parse(config_json);
    doc["imu_rate_hz"] = walk.rate_hz;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = plugin_dirs;
    o.keep_attitudes = true;
    // The walker is told where it starts and which way it faces, as in an app.
    for (int i = 0; i < 3; ++i) o.start_enu_m[i] = out.truth.front().pos_enu_m[i];
    o.heading_deg = out.truth.front().heading_deg;
    const ReplayResult r = replay(o, out.records());
    if (!r.error.empty()) throw std::runtime_error("sim " + walk.route + ": " + r.error);
    WalkScore s = score(r, eval::sim_truth(out, route), eval::Alignment::start_point);
    s.true_steps = out.step_times_s.size();
    s.true_distance_m = out.distance_m;
    s.distance_error_pct = 100.0 * (s.distance_m - out.distance_m) / out.distance_m;
    return s;
}

}  // namespace pednav::chest_eval
