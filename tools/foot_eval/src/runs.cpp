// SPDX-License-Identifier: Apache-2.0
#include <pednav_foot_eval/runs.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_io/sensor_log.hpp>

namespace pednav::foot_eval {

ReplayResult run_log(const io::SensorLog& log, const std::string& config_json,
                     const std::vector<std::string>& plugin_dirs, const std::string& what) {
    auto doc = nlohmann::json::parse(config_json);
    const io::StreamInfo* s = log.stream("accel");
    doc["imu_rate_hz"] = s ? s->median_rate_hz : 0.0;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = plugin_dirs;
    ReplayResult r = replay(o, io::merged_records(log));
    if (!r.error.empty()) throw std::runtime_error(what + ": " + r.error);
    return r;
}

ReplayResult run_recording(const std::string& path, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs) {
    return run_log(io::read_sensor_file(path), config_json, plugin_dirs, path);
}

const pn_position_t& position_at(const ReplayResult& r, double t_s) {
    if (r.positions.empty()) throw std::runtime_error("no positions");
    const int64_t t = static_cast<int64_t>(std::llround(t_s * 1e9));
    auto it = std::upper_bound(r.positions.begin(), r.positions.end(), t,
                               [](int64_t v, const pn_position_t& p) { return v < p.header.t_ns; });
    if (it == r.positions.begin()) return r.positions.front();
    return *(it - 1);
}

double stride_path_m(const ReplayResult& r) {
    double d = 0;
    for (const auto& s : r.strides) d += s.length_m;
    return d;
}

}  // namespace pednav::foot_eval
