// SPDX-License-Identifier: Apache-2.0
// JSON of an input (pednav inspect --json, the "input" of a run summary) and
// the run summary. Keys are listed in docs/formats.md; only additions allowed.
#include <cmath>
#include <set>

#include "pednav_io/gnss_log.hpp"
#include "pednav_io/writers.hpp"

namespace pednav::io {

nlohmann::json sensor_log_json(const SensorLog& log) {
    using nlohmann::json;
    json streams = json::array();
    for (const auto& s : log.streams) {
        streams.push_back({{"name", s.name},
                           {"count", s.count},
                           {"rate_hz", s.rate_hz},
                           {"median_rate_hz", s.median_rate_hz},
                           {"duration_s", s.duration_s},
                           {"t_first_s", s.t_first_s},
                           {"t_last_s", s.t_last_s},
                           {"units_found", s.units_found},
                           {"units_converted", s.units_converted},
                           {"gaps", s.gaps},
                           {"bad_rows", s.bad_rows}});
    }
    json issues = json::array();
    for (const auto& i : log.issues) issues.push_back({{"line", i.line}, {"message", i.message}});
    json truth_origin = nullptr;
    if (log.truth_origin.known) {
        truth_origin = {{"lat_deg", log.truth_origin.lat_deg}, {"lon_deg", log.truth_origin.lon_deg}};
    }
    json j = {{"path", log.path},
              {"format", log.format},
              {"axes", log.axes},
              {"records",
               {{"imu", log.records.imu},
                {"mag", log.records.mag},
                {"baro", log.records.baro},
                {"gnss", log.records.gnss},
                {"truth", log.truth.size()}}},
              {"streams", streams},
              {"truth_origin", truth_origin},
              {"issues", issues},
              {"issues_not_listed", log.issues_not_listed},
              {"notes", log.notes}};
    if (!log.gnss.empty()) j["gnss_fixes"] = gnss_fixes_json(log.gnss);
    if (log.utc_ns_at_zero != 0) j["utc_at_zero"] = iso_utc(log.utc_ns_at_zero);
    return j;
}

double track_length_m(const std::vector<pn_position_t>& positions) {
    double length_m = 0.0;
    for (size_t i = 1; i < positions.size(); ++i) {
        length_m += std::hypot(positions[i].pos_enu_m[0] - positions[i - 1].pos_enu_m[0],
                               positions[i].pos_enu_m[1] - positions[i - 1].pos_enu_m[1]);
    }
    return length_m;
}

void RunTotals::add(const pn_position_t& p) {
    if (positions++ == 0) {
        first = p;
    } else {
        distance_m += std::hypot(p.pos_enu_m[0] - last.pos_enu_m[0], p.pos_enu_m[1] - last.pos_enu_m[1]);
    }
    last = p;
    if (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) floors.insert(p.floor);
}

void RunTotals::add(const pn_stride_t& s) {
    ++strides;
    stride_length_sum_m += s.length_m;
}

nlohmann::json run_summary_json(const SensorLog& input, const std::string& describe_json,
                                const std::vector<pn_position_t>& positions,
                                const std::vector<pn_stride_t>& strides,
                                const std::vector<std::string>& warnings) {
    RunTotals totals;
    for (const auto& p : positions) totals.add(p);
    for (const auto& s : strides) totals.add(s);
    return run_summary_json(input, describe_json, totals, warnings);
}

nlohmann::json run_summary_json(const SensorLog& input, const std::string& describe_json, const RunTotals& totals,
                                const std::vector<std::string>& warnings) {
    using nlohmann::json;
    json describe = describe_json.empty() ? json(nullptr) : json::parse(describe_json, nullptr, false);
    if (describe.is_discarded()) describe = json(describe_json);

    json final_position = nullptr;
    double duration_s = 0.0;
    if (totals.positions > 0) {
        const auto& last = totals.last;
        final_position = {last.pos_enu_m[0], last.pos_enu_m[1], last.pos_enu_m[2]};
        duration_s = static_cast<double>(last.header.t_ns - totals.first.header.t_ns) * 1e-9;
    }
    json summary = {
        {"format", "pednav-run-summary/1"},
        {"input", sensor_log_json(input)},
        {"engine", describe.is_object() && describe.contains("engine") ? describe["engine"] : json(nullptr)},
        {"pipeline", describe.is_object() && describe.contains("pipeline") ? describe["pipeline"] : describe},
        {"samples",
         {{"imu", input.records.imu},
          {"mag", input.records.mag},
          {"baro", input.records.baro},
          {"gnss", input.records.gnss}}},
        {"positions", totals.positions},
        {"steps", totals.strides},
        {"distance_m", totals.distance_m},
        {"stride_length_sum_m", totals.stride_length_sum_m},
        {"duration_s", duration_s},
        {"final_position_enu_m", final_position},
        {"floors", totals.floors},
        {"warnings", warnings},
    };
    if (describe.is_object() && describe.contains("counters")) summary["counters"] = describe["counters"];
    return summary;
}

}  // namespace pednav::io
