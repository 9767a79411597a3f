// SPDX-License-Identifier: Apache-2.0
#include "matched_walks.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_indoor_map/wall_crossings.hpp>
#include <pednav_sim/building_map.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::test {

namespace {

std::string read_text(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

int count_crossings(const indoor_map::Map& m, const std::vector<pn_position_t>& track) {
    std::vector<indoor_map::Point2> points;
    std::vector<int> floors;
    for (const pn_position_t& p : track) {
        points.push_back({p.pos_enu_m[0], p.pos_enu_m[1]});
        floors.push_back(p.floor);
    }
    return static_cast<int>(indoor_map::wall_crossings(m, points, floors).size());
}

}  // namespace

std::string walk_map_document(const eval::SimulatedWalk& walk) { return sim::building_map(eval::sim_route(walk)).dump(); }

indoor_map::Map walk_map(const eval::SimulatedWalk& walk) {
    const std::string doc = walk_map_document(walk);
    return indoor_map::read_geojson_map(doc, indoor_map::geojson_map_origin(doc));
}

MatchedWalkScore run_matched_walk(const MatchedWalk& w) {
    const sim::Route route = eval::sim_route(w.walk);
    const sim::SimOptions options = eval::sim_options(w.walk);
    const sim::SimOutput sim = sim::simulate(route, options);
    const std::string document = w.map_document.empty() ? walk_map_document(w.walk) : w.map_document;
    const indoor_map::Map map = indoor_map::read_geojson_map(document, indoor_map::geojson_map_origin(document));
    const std::string map_path = w.work_dir + "/" + route.name + ".geojson";
    std::ofstream(map_path) << document;

    const std::string preset = read_text(w.config_path);
    const std::string mount = nlohmann::json::parse(preset).at("mount");
    nlohmann::json stage = {{"plugin", "org.pednav.map.particle_filter"}, {"params", w.matcher_params}};
    const nlohmann::json patch = {{"pipelines", {{mount, {{"map_matcher", stage}}}}},
                                  {"map", {{"path", map_path}, {"format", "pednav.map/1"}}},
                                  {"imu_rate_hz", sim.rate_hz}};
    ReplayOptions ro;
    ro.config_json = eval::patched_config(preset, patch);
    ro.plugin_dirs = {w.plugin_dir};
    const sim::TruthSample& t0 = sim.truth.front();
    ro.start_enu_m[0] = t0.pos_enu_m[0] + w.start_offset_m[0];
    ro.start_enu_m[1] = t0.pos_enu_m[1] + w.start_offset_m[1];
    ro.start_enu_m[2] = 0.0;
    ro.heading_deg = t0.heading_deg;
    const ReplayResult r = replay(ro, sim.records());
    if (!r.error.empty()) throw std::runtime_error(route.name + ": " + r.error);

    // The same walk without the map matcher, for the figures beside.
    ReplayOptions raw_options = ro;
    raw_options.config_json = eval::patched_config(preset, {{"imu_rate_hz", sim.rate_hz}});
    const ReplayResult raw = replay(raw_options, sim.records());

    MatchedWalkScore s;
    s.positions = r.positions.size();
    s.track = r.positions;
    s.describe_json = r.describe_json;
    auto truth_at = [&](int64_t t_ns) -> const sim::TruthSample& {
        const auto k = static_cast<size_t>(std::llround(1e-9 * static_cast<double>(t_ns) * sim.rate_hz));
        return sim.truth.at(std::min(k, sim.truth.size() - 1));
    };
    std::vector<double> horizontal, raw_horizontal;
    std::vector<int> floor_diff;
    size_t right = 0;
    s.min_live = UINT32_MAX;
    for (const pn_position_t& p : r.positions) {
        const sim::TruthSample& t = truth_at(p.header.t_ns);
        horizontal.push_back(std::hypot(p.pos_enu_m[0] - t.pos_enu_m[0], p.pos_enu_m[1] - t.pos_enu_m[1]));
        const int floor = (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) ? p.floor : 0;
        floor_diff.push_back(floor - t.floor);
        right += floor == t.floor;
        if (p.header.flags & PN_POSITION_FLAG_HAS_PARTICLES) s.min_live = std::min(s.min_live, p.live_particles);
        s.recovered_flags += (p.header.flags & PN_POSITION_FLAG_RECOVERED) != 0;
        s.recoveries = p.recoveries;
    }
    for (const pn_position_t& p : raw.positions) {
        const sim::TruthSample& t = truth_at(p.header.t_ns);
        raw_horizontal.push_back(std::hypot(p.pos_enu_m[0] - t.pos_enu_m[0], p.pos_enu_m[1] - t.pos_enu_m[1]));
    }
    s.floor_right = s.positions ? static_cast<double>(right) / static_cast<double>(s.positions) : 0.0;
    s.ipin_p75_m = eval::ipin_score(horizontal, floor_diff);
    s.horizontal_p75_m = eval::percentile(horizontal, 75);
    s.horizontal_max_m = horizontal.empty() ? NAN : *std::max_element(horizontal.begin(), horizontal.end());
    s.raw_p75_m = eval::percentile(raw_horizontal, 75);
    s.crossings = count_crossings(map, r.positions);
    return s;
}

}  // namespace pednav::test
