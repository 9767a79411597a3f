// SPDX-License-Identifier: Apache-2.0
#include "matched_recordings.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_engine/replay.hpp>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_eval/walks.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_indoor_map/map_convert.hpp>
#include <pednav_indoor_map/wall_crossings.hpp>
#include <pednav_io/sensor_log.hpp>

namespace pednav::test {

namespace {

std::string read_text(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

const pn_position_t& position_at(const std::vector<pn_position_t>& track, double t_s) {
    if (track.empty()) throw std::runtime_error("no positions");
    const auto t = static_cast<int64_t>(std::llround(t_s * 1e9));
    auto it = std::upper_bound(track.begin(), track.end(), t,
                               [](int64_t v, const pn_position_t& p) { return v < p.header.t_ns; });
    return it == track.begin() ? track.front() : *(it - 1);
}

}  // namespace

MatchedRecordingScore run_humolire_walk(const std::string& data_dir, const std::string& walk,
                                        const std::string& preset_path, const std::string& plugin_dir,
                                        const std::string& work_dir) {
    const eval::RecordedWalk w = eval::humolire_walk(data_dir, walk);
    // The keypoints and the converted map are both in HuMoLiRe's metres (x
    // right, y up from the map image's bottom edge); the walk starts at its
    // start point with its heading.
    const eval::Truth truth = eval::read_humolire(w.truth_path);
    const std::string map_file = data_dir + "/humolire-phone/maps/map_data.json";
    const std::string document = indoor_map::humolire_to_geojson({map_file, read_text(map_file)}, {});
    const indoor_map::Map map = indoor_map::read_geojson_map(document, std::nullopt);
    const std::string map_path = work_dir + "/humolire-" + walk + ".geojson";
    std::ofstream(map_path) << document;

    // The walker's height from participant.txt, as an app knows its user's.
    const std::string preset = eval::with_user_height(read_text(preset_path), w.user_height_m);
    const std::string mount = nlohmann::json::parse(preset).at("mount");
    const io::SensorLog log = io::read_sensor_file(w.input);
    const io::StreamInfo* accel = log.stream("accel");
    const double rate = accel ? accel->median_rate_hz : 0.0;
    ReplayOptions o;
    o.plugin_dirs = {plugin_dir};
    o.heading_deg = truth.start_heading_deg;
    o.start_enu_m[0] = truth.start_x_m;
    o.start_enu_m[1] = truth.start_y_m;
    o.config_json = eval::patched_config(
        preset, {{"imu_rate_hz", rate},
                 {"pipelines", {{mount, {{"map_matcher", {{"plugin", "org.pednav.map.particle_filter"}}}}}}},
                 {"map", {{"path", map_path}, {"format", "pednav.map/1"}}}});
    const auto records = io::merged_records(log);
    const ReplayResult with = replay(o, records);
    if (!with.error.empty()) throw std::runtime_error(walk + ": " + with.error);
    o.config_json = eval::patched_config(preset, {{"imu_rate_hz", rate}});
    const ReplayResult without = replay(o, records);
    if (!without.error.empty()) throw std::runtime_error(walk + ": " + without.error);

    MatchedRecordingScore s;
    std::vector<double> e_with, e_without;
    for (const eval::TruthPoint& p : truth.points) {
        const pn_position_t& a = position_at(with.positions, p.t_s);
        const pn_position_t& b = position_at(without.positions, p.t_s);
        e_with.push_back(std::hypot(a.pos_enu_m[0] - p.x_m, a.pos_enu_m[1] - p.y_m));
        e_without.push_back(std::hypot(b.pos_enu_m[0] - p.x_m, b.pos_enu_m[1] - p.y_m));
    }
    s.with_map = eval::error_stats(e_with);
    s.without_map = eval::error_stats(e_without);
    std::vector<indoor_map::Point2> points;
    std::vector<int> floors;
    s.min_live = UINT32_MAX;
    for (const pn_position_t& p : with.positions) {
        points.push_back({p.pos_enu_m[0], p.pos_enu_m[1]});
        floors.push_back(p.floor);
        s.recoveries = p.recoveries;
        if (p.header.flags & PN_POSITION_FLAG_HAS_PARTICLES) s.min_live = std::min(s.min_live, p.live_particles);
    }
    s.crossings = static_cast<int>(indoor_map::wall_crossings(map, points, floors).size());
    s.positions = with.positions.size();
    return s;
}

}  // namespace pednav::test

namespace pednav::test {

BibaScore run_biba_route(const std::string& data_dir, const BibaRun& run, const std::string& preset_path,
                         const std::string& plugin_dir, const std::string& work_dir) {
    const std::string dir = data_dir + "/biba-chest-xsens/map/";
    auto file = [&](const char* name) { return indoor_map::SourceFile{dir + name, read_text(dir + name)}; };
    const indoor_map::RairyuuMapFiles files{file("core.txt"), file("node.txt"), file("link.txt"),
                                            file("polygon.txt"), file("arrow.txt")};
    indoor_map::MapConversion conversion;
    conversion.scale_m_per_px = run.scale_m_per_px;
    const std::string document = indoor_map::rairyuu_to_geojson(files, conversion);
    const indoor_map::Map map = indoor_map::read_geojson_map(document, std::nullopt);
    const std::string map_path = work_dir + "/biba-" + run.route + ".geojson";
    std::ofstream(map_path) << document;
    const std::string preset = read_text(preset_path);
    const std::string mount = nlohmann::json::parse(preset).at("mount");
    const io::SensorLog log = io::read_sensor_file(data_dir + "/biba-chest-xsens/" + run.route + ".txt");
    const io::StreamInfo* accel = log.stream("accel");
    ReplayOptions o;
    o.plugin_dirs = {plugin_dir};
    o.heading_deg = run.heading_deg;
    o.start_enu_m[0] = run.start_enu_m[0];
    o.start_enu_m[1] = run.start_enu_m[1];
    o.config_json = eval::patched_config(
        preset, {{"imu_rate_hz", accel ? accel->median_rate_hz : 0.0},
                 {"pipelines", {{mount, {{"map_matcher", {{"plugin", "org.pednav.map.particle_filter"}}}}}}},
                 {"map", {{"path", map_path}, {"format", "pednav.map/1"}}}});
    const ReplayResult r = replay(o, io::merged_records(log));
    if (!r.error.empty()) throw std::runtime_error(run.route + ": " + r.error);
    BibaScore b;
    MatchedRecordingScore& s = b.matched;
    std::vector<indoor_map::Point2> points;
    std::vector<int> floors;
    s.min_live = UINT32_MAX;
    for (const pn_position_t& p : r.positions) {
        if (!points.empty())
            b.distance_m +=
                std::hypot(p.pos_enu_m[0] - points.back().e_m, p.pos_enu_m[1] - points.back().n_m);
        points.push_back({p.pos_enu_m[0], p.pos_enu_m[1]});
        floors.push_back(p.floor);
        s.recoveries = p.recoveries;
        if (p.header.flags & PN_POSITION_FLAG_HAS_PARTICLES)
            s.min_live = std::min(s.min_live, p.live_particles);
    }
    if (!points.empty()) {
        b.end_enu_m[0] = points.back().e_m;
        b.end_enu_m[1] = points.back().n_m;
    }
    s.crossings = static_cast<int>(indoor_map::wall_crossings(map, points, floors).size());
    s.positions = r.positions.size();
    return b;
}

}  // namespace pednav::test
