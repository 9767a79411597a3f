// SPDX-License-Identifier: Apache-2.0
#include "config.hpp"

#include <nlohmann/json.hpp>

#include "pednav_strict_json/strict_json.hpp"

namespace pednav::engine {

const char* role_name(Role role) {
    switch (role) {
        case Role::step_detector: return "step_detector";
        case Role::attitude_estimator: return "attitude_estimator";
        case Role::position_filter: return "position_filter";
        case Role::map_matcher: return "map_matcher";
    }
    return "unknown";
}

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& message) {
    throw ConfigProblem{PN_E_INVALID_CONFIG, where, message};
}

void check_keys(const nlohmann::json& obj, const std::string& where,
                std::initializer_list<const char*> allowed) {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
        bool ok = false;
        for (const char* a : allowed) ok = ok || it.key() == a;
        if (!ok) fail(where + "/" + it.key(), "unknown key \"" + it.key() + "\" in " + (where.empty() ? "the config" : where));
    }
}

// "on_failure", "call_budget_ms", "over_budget" of a stage.
void parse_failure_policy(const nlohmann::json& j, const std::string& where, StageConfig& s) {
    if (auto f = j.find("on_failure"); f != j.end()) {
        if (!f->is_string() || (*f != "reset" && *f != "stop"))
            fail(where + "/on_failure", "\"on_failure\" must be \"reset\" or \"stop\"");
        s.on_failure = *f == "stop" ? OnFailure::stop : OnFailure::reset;
    }
    if (auto b = j.find("call_budget_ms"); b != j.end()) {
        if (!b->is_number() || !(b->get<double>() >= 0.0 && b->get<double>() <= 60000.0))
            fail(where + "/call_budget_ms", "\"call_budget_ms\" must be a number of milliseconds in [0, 60000]");
        s.call_budget_ms = b->get<double>();
    }
    if (auto o = j.find("over_budget"); o != j.end()) {
        if (!o->is_string() || (*o != "warn" && *o != "stop"))
            fail(where + "/over_budget", "\"over_budget\" must be \"warn\" or \"stop\"");
        if (!j.contains("call_budget_ms")) fail(where, "\"over_budget\" needs \"call_budget_ms\"");
        s.over_budget = *o == "stop" ? OverBudget::stop : OverBudget::warn;
    }
}

StageConfig parse_stage(const nlohmann::json& j, Role role, const std::string& where) {
    if (!j.is_object()) fail(where, std::string(role_name(role)) + " must be an object with \"plugin\" and \"params\"");
    check_keys(j, where, {"plugin", "params", "on_failure", "call_budget_ms", "over_budget"});
    auto p = j.find("plugin");
    if (p == j.end() || !p->is_string() || p->get<std::string>().empty())
        fail(where + "/plugin", "\"plugin\" must name a plugin id");
    StageConfig s{role, p->get<std::string>(), "{}", where};
    auto params = j.find("params");
    if (params != j.end() && !params->is_null()) {
        if (!params->is_object()) fail(where + "/params", "\"params\" must be an object");
        s.params_json = params->dump();
    }
    parse_failure_policy(j, where, s);
    return s;
}

double number_in(const nlohmann::json& obj, const char* key, const std::string& where, double min, double max,
                 const char* unit) {
    const auto& v = obj.at(key);
    if (!v.is_number() || !(v.get<double>() >= min && v.get<double>() <= max))
        fail(where + "/" + key, std::string("\"") + key + "\" must be a number of " + unit + " in [" +
                                    nlohmann::json(min).dump() + ", " + nlohmann::json(max).dump() + "]");
    return v.get<double>();
}

void parse_origin(const nlohmann::json& o, EngineConfig& cfg) {
    if (!o.is_object())
        fail("/origin", "\"origin\" must be an object: {\"lat_deg\", \"lon_deg\", \"height_m\"} and/or "
                        "{\"from_fix_max_h_accuracy_m\"}");
    check_keys(o, "/origin", {"lat_deg", "lon_deg", "height_m", "from_fix_max_h_accuracy_m"});
    const bool lat = o.contains("lat_deg"), lon = o.contains("lon_deg");
    if (lat != lon) fail(lat ? "/origin/lon_deg" : "/origin/lat_deg", "an origin needs both lat_deg and lon_deg");
    if (o.contains("height_m") && !lat) fail("/origin/height_m", "height_m needs lat_deg and lon_deg");
    if (lat) {
        cfg.has_origin = true;
        cfg.origin.lat_deg = number_in(o, "lat_deg", "/origin", -90.0, 90.0, "degrees");
        cfg.origin.lon_deg = number_in(o, "lon_deg", "/origin", -180.0, 180.0, "degrees");
        cfg.origin.height_m = o.contains("height_m") ? number_in(o, "height_m", "/origin", -1e5, 1e5, "metres") : 0.0;
    }
    if (o.contains("from_fix_max_h_accuracy_m"))
        cfg.origin_fix_max_h_accuracy_m = number_in(o, "from_fix_max_h_accuracy_m", "/origin", 0.0, 1e6, "metres");
}

void parse_map(const nlohmann::json& m, EngineConfig& cfg) {
    if (!m.is_object()) fail("/map", "\"map\" must be an object: {\"path\": FILE, \"format\": \"pednav.map/1\"}");
    check_keys(m, "/map", {"path", "format"});
    auto path = m.find("path");
    if (path == m.end() || !path->is_string() || path->get<std::string>().empty())
        fail("/map/path", "\"path\" must name the map file");
    cfg.map_path = path->get<std::string>();
    if (auto f = m.find("format"); f != m.end()) {
        if (!f->is_string() || f->get<std::string>().empty()) fail("/map/format", "\"format\" must be a map format id");
        cfg.map_format = f->get<std::string>();
    }
}

}  // namespace

EngineConfig parse_config(const std::string& text) {
    nlohmann::json doc;
    try {
        doc = strict_json::parse(text);
    } catch (const strict_json::Error& e) {
        fail(e.pointer, std::string("config: ") + e.what());
    }
    if (!doc.is_object())
        fail("", std::string("config must be a JSON object, not ") + (doc.is_array() ? "an array" : "a ") +
                     (doc.is_array() ? "" : doc.type_name()));
    check_keys(doc, "", {"format", "mount", "imu_rate_hz", "pipelines", "description", "input", "origin", "map"});
    // "input" configures the file readers of the tools (format, column map);
    // the engine itself does not read files, but checks it like every key.
    if (auto in = doc.find("input"); in != doc.end()) {
        if (!in->is_object()) fail("/input", "\"input\" must be an object (reader settings: format, column_map)");
        check_keys(*in, "/input", {"format", "column_map"});
        if (auto f = in->find("format"); f != in->end() && !f->is_string())
            fail("/input/format", "\"format\" must be a reader name (pednav inspect --formats)");
        if (auto m = in->find("column_map"); m != in->end() && !m->is_object())
            fail("/input/column_map", "\"column_map\" must be an object (docs/formats.md)");
    }
    auto format = doc.find("format");
    if (format == doc.end() || !format->is_string() || format->get<std::string>() != "pednav-config/1")
        fail("/format", "\"format\" must be \"pednav-config/1\"");

    EngineConfig cfg;
    std::string mounts;
    for (const char* m : kMounts) mounts += (mounts.empty() ? "" : ", ") + std::string(m);
    auto m = doc.find("mount");
    if (m == doc.end() || !m->is_string()) fail("/mount", "\"mount\" must be one of " + mounts);
    cfg.mount = m->get<std::string>();
    bool known_mount = false;
    for (const char* k : kMounts) known_mount = known_mount || cfg.mount == k;
    if (!known_mount) fail("/mount", "mount \"" + cfg.mount + "\" is not one of " + mounts);
    if (auto r = doc.find("imu_rate_hz"); r != doc.end()) {
        if (!r->is_number() || r->get<double>() < 0 || r->get<double>() > 100000)
            fail("/imu_rate_hz", "\"imu_rate_hz\" must be a number of Hz in [0, 100000]");
        cfg.imu_rate_hz = r->get<double>();
    }
    auto pipelines = doc.find("pipelines");
    if (pipelines == doc.end() || !pipelines->is_object()) fail("/pipelines", "\"pipelines\" must be an object keyed by mount");
    check_keys(*pipelines, "/pipelines", {"foot", "chest", "handheld", "waist"});
    auto pipe = pipelines->find(cfg.mount);
    if (pipe == pipelines->end())
        throw ConfigProblem{PN_E_NOT_FOUND, "/pipelines/" + cfg.mount, "the config has no pipeline for mount " + cfg.mount};
    const std::string base = "/pipelines/" + cfg.mount;
    if (!pipe->is_object()) fail(base, "a pipeline must be an object keyed by role");
    check_keys(*pipe, base, {"step_detector", "attitude_estimator", "position_filter", "map_matcher"});
    for (int r = 0; r < kRoleCount; ++r) {
        const Role role = static_cast<Role>(r);
        auto s = pipe->find(role_name(role));
        if (s != pipe->end()) cfg.stages.push_back(parse_stage(*s, role, base + "/" + role_name(role)));
    }
    if (cfg.stages.empty()) fail(base, "the pipeline for " + cfg.mount + " has no stage");
    if (auto o = doc.find("origin"); o != doc.end()) parse_origin(*o, cfg);
    if (auto map = doc.find("map"); map != doc.end()) parse_map(*map, cfg);
    return cfg;
}

}  // namespace pednav::engine
