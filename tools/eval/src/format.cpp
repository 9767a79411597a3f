// SPDX-License-Identifier: Apache-2.0
#include <cstdio>

#include <pednav_eval/metrics.hpp>

namespace pednav::eval {

namespace {

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json axis_json(const AxisStats& a) {
    return {{"min", num(a.min)}, {"max", num(a.max)}, {"mean", num(a.mean)}, {"sd", num(a.sd)}};
}

nlohmann::json error_json(const ErrorStats& e) {
    return {{"n", e.n},        {"mean", num(e.mean)}, {"median", num(e.median)}, {"p75", num(e.p75)},
            {"sd", num(e.sd)}, {"max", num(e.max)},   {"rms", num(e.rms)}};
}

std::string fmt(double v, const char* unit, int decimals = 2) {
    if (!std::isfinite(v)) return "-";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f%s%s", decimals, v, unit[0] ? " " : "", unit);
    return buf;
}

void row(std::string& out, const std::string& name, const std::string& value) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "  %-34s %s\n", name.c_str(), value.c_str());
    out += buf;
}

}  // namespace

nlohmann::json to_json(const Metrics& m) {
    nlohmann::json j;
    j["truth_kind"] = m.truth_kind;
    j["alignment"] = {
        {"mode", alignment_name(m.alignment.mode)},
        {"rotation_deg", m.alignment.rotation_deg},
        {"translation_m",
         {m.alignment.to_m[0] - m.alignment.from_m[0], m.alignment.to_m[1] - m.alignment.from_m[1]}},
        {"z_offset_m", m.alignment.z_offset_m}};
    j["checkpoints"] = m.checkpoints;
    j["dx_m"] = axis_json(m.dx_m);
    j["dy_m"] = axis_json(m.dy_m);
    j["horizontal_error_m"] = error_json(m.horizontal_m);
    j["final_error_m"] = num(m.final_error_m);
    j["ipin_score_m"] = num(m.ipin_score_m);
    j["floor_correct_pct"] = num(m.floor_correct_pct);
    j["heading_error_deg"] = error_json(m.heading_error_deg);
    j["height_error_m"] = {{"mean", num(m.height_error_mean_m)}, {"sd", num(m.height_error_sd_m)}};
    j["loop_closure"] = {{"horizontal_m", num(m.loop_closure_m)},
                         {"3d_m", num(m.loop_closure_3d_m)},
                         {"pct_of_distance", num(m.loop_closure_pct)}};
    j["distance_m"] = num(m.distance_m);
    j["truth_distance_m"] = num(m.truth_distance_m);
    j["step_count"] = m.step_count >= 0 ? nlohmann::json(m.step_count) : nlohmann::json(nullptr);
    j["truth_step_count"] =
        m.truth_step_count >= 0 ? nlohmann::json(m.truth_step_count) : nlohmann::json(nullptr);
    j["legs"] = nlohmann::json::array();
    for (size_t i = 0; i < m.leg_lengths_m.size(); ++i)
        j["legs"].push_back({{"length_m", m.leg_lengths_m[i]}, {"error_pct", m.leg_errors_pct[i]}});
    return j;
}

std::string format_table(const Metrics& m) {
    std::string out;
    char buf[160];
    std::snprintf(buf, sizeof buf, "truth: %s, alignment: %s (rotation %.2f deg), %zu checkpoints\n",
                  m.truth_kind.c_str(), alignment_name(m.alignment.mode), m.alignment.rotation_deg,
                  m.checkpoints);
    out += buf;
    if (m.checkpoints > 0) {
        row(out, "horizontal error mean / median",
            fmt(m.horizontal_m.mean, "m") + " / " + fmt(m.horizontal_m.median, "m"));
        row(out, "horizontal error p75 / sd / max",
            fmt(m.horizontal_m.p75, "m") + " / " + fmt(m.horizontal_m.sd, "m") + " / " +
                fmt(m.horizontal_m.max, "m"));
        row(out, "final error", fmt(m.final_error_m, "m"));
        row(out, "dx min / max / mean / sd",
            fmt(m.dx_m.min, "") + " / " + fmt(m.dx_m.max, "") + " / " + fmt(m.dx_m.mean, "") + " / " +
                fmt(m.dx_m.sd, "m"));
        row(out, "dy min / max / mean / sd",
            fmt(m.dy_m.min, "") + " / " + fmt(m.dy_m.max, "") + " / " + fmt(m.dy_m.mean, "") + " / " +
                fmt(m.dy_m.sd, "m"));
        row(out, "IPIN score (p75, 15 m per floor)", fmt(m.ipin_score_m, "m"));
    }
    if (std::isfinite(m.floor_correct_pct)) row(out, "floor correct", fmt(m.floor_correct_pct, "%", 1));
    if (m.heading_error_deg.n > 0)
        row(out, "heading error mean / max",
            fmt(m.heading_error_deg.mean, "deg") + " / " + fmt(m.heading_error_deg.max, "deg"));
    if (std::isfinite(m.height_error_mean_m))
        row(out, "height error mean / sd",
            fmt(m.height_error_mean_m, "m") + " / " + fmt(m.height_error_sd_m, "m"));
    if (std::isfinite(m.loop_closure_m))
        row(out, "loop closure",
            fmt(m.loop_closure_m, "m") + " (" + fmt(m.loop_closure_pct, "% of distance", 3) + ")");
    row(out, "distance (track / truth)", fmt(m.distance_m, "m") + " / " + fmt(m.truth_distance_m, "m"));
    if (m.step_count >= 0 || m.truth_step_count >= 0)
        row(out, "steps (track / truth)",
            (m.step_count >= 0 ? std::to_string(m.step_count) : std::string("-")) + " / " +
                (m.truth_step_count >= 0 ? std::to_string(m.truth_step_count) : std::string("-")));
    for (size_t i = 0; i < m.leg_lengths_m.size(); ++i)
        row(out, "leg " + std::to_string(i + 1) + " length",
            fmt(m.leg_lengths_m[i], "m") + " (" + fmt(m.leg_errors_pct[i], "%", 1) + ")");
    return out;
}

}  // namespace pednav::eval
