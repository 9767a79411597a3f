// SPDX-License-Identifier: Apache-2.0
#include <pednav_sim/route.hpp>

#include <cmath>
#include <set>
#include <stdexcept>

namespace pednav::sim {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw std::runtime_error("route: " + where + ": " + what);
}

double number(const json& j, const std::string& where, double lo, double hi) {
    if (!j.is_number()) fail(where, "must be a number");
    const double v = j.get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        fail(where, "must be within " + std::to_string(lo) + " .. " + std::to_string(hi));
    return v;
}

bool boolean(const json& j, const std::string& where) {
    if (!j.is_boolean()) fail(where, "must be true or false");
    return j.get<bool>();
}

void vec(const json& j, const std::string& where, size_t n, double* out) {
    if (!j.is_array() || j.size() != n) fail(where, "must be an array of " + std::to_string(n) + " numbers");
    for (size_t i = 0; i < n; ++i) out[i] = number(j[i], where + "/" + std::to_string(i), -1e6, 1e6);
}

void check_keys(const json& j, const std::string& where, const std::set<std::string>& known) {
    if (!j.is_object()) fail(where.empty() ? "/" : where, "must be an object");
    for (auto it = j.begin(); it != j.end(); ++it)
        if (!known.count(it.key())) fail(where + "/" + it.key(), "unknown key");
}

GnssQuality parse_gnss(const json& j, const std::string& where) {
    if (j.is_string()) {
        try {
            return gnss_quality_preset(j.get<std::string>());
        } catch (const std::runtime_error&) {
            fail(where, "must be \"good\", \"degraded\", \"none\" or an object");
        }
    }
    check_keys(j, where, {"fixes", "error_scale", "satellites"});
    GnssQuality q;
    q.name = "custom";
    if (j.contains("fixes")) q.fixes = boolean(j["fixes"], where + "/fixes");
    if (j.contains("error_scale")) q.error_scale = number(j["error_scale"], where + "/error_scale", 0.1, 100.0);
    if (j.contains("satellites")) {
        if (!j["satellites"].is_number_integer()) fail(where + "/satellites", "must be an integer");
        q.satellites = static_cast<int>(number(j["satellites"], where + "/satellites", 0.0, 64.0));
    }
    return q;
}

json gnss_to_json(const GnssQuality& q) {
    if (q.name != "custom") return q.name;
    return {{"fixes", q.fixes}, {"error_scale", q.error_scale}, {"satellites", q.satellites}};
}

}  // namespace

GnssQuality gnss_quality_preset(const std::string& name) {
    GnssQuality q;
    q.name = name;
    if (name == "good") return q;
    if (name == "degraded") {
        q.error_scale = 4.0;
        q.satellites = 6;
        return q;
    }
    if (name == "none") {
        q.fixes = false;
        q.satellites = 0;
        return q;
    }
    throw std::runtime_error("sim: unknown GNSS quality '" + name + "' (good, degraded or none)");
}

const GnssQuality& segment_gnss(const Route& route, size_t segment) {
    static const GnssQuality good = gnss_quality_preset("good"), none = gnss_quality_preset("none");
    if (segment + 1 >= route.waypoints.size()) return none;
    const Waypoint& w = route.waypoints[segment + 1];
    if (w.gnss_given) return w.gnss;
    return w.outdoor ? good : none;
}

Route parse_route(const json& j) {
    check_keys(j, "",
               {"format", "name", "description", "waypoints", "speed_mps", "step_length_m", "stance_fraction",
                "stair_rise_m", "stair_run_m", "stairs_step_period_s", "floor_height_m", "start_still_s",
                "end_still_s", "origin", "mag_disturbances", "walls", "gnss_jumps"});
    Route r;
    if (j.contains("format") && j["format"] != "pednav-route/1")
        fail("/format", "must be \"pednav-route/1\"");
    if (j.contains("name")) {
        if (!j["name"].is_string()) fail("/name", "must be a string");
        r.name = j["name"].get<std::string>();
    }
    if (j.contains("description")) {
        if (!j["description"].is_string()) fail("/description", "must be a string");
        r.description = j["description"].get<std::string>();
    }
    auto opt = [&](const char* key, double& v, double lo, double hi) {
        if (j.contains(key)) v = number(j[key], std::string("/") + key, lo, hi);
    };
    opt("speed_mps", r.speed_mps, 0.2, 4.0);
    opt("step_length_m", r.step_length_m, 0.2, 1.5);
    opt("stance_fraction", r.stance_fraction, 0.1, 0.6);
    opt("stair_rise_m", r.stair_rise_m, 0.05, 0.3);
    opt("stair_run_m", r.stair_run_m, 0.1, 0.6);
    opt("stairs_step_period_s", r.stairs_step_period_s, 0.3, 2.0);
    opt("floor_height_m", r.floor_height_m, 2.0, 10.0);
    opt("start_still_s", r.start_still_s, 0.0, 600.0);
    opt("end_still_s", r.end_still_s, 0.0, 600.0);
    if (j.contains("origin")) {
        const json& o = j["origin"];
        check_keys(o, "/origin", {"lat_deg", "lon_deg", "height_m"});
        if (o.contains("lat_deg")) r.origin_lat_deg = number(o["lat_deg"], "/origin/lat_deg", -85.0, 85.0);
        if (o.contains("lon_deg")) r.origin_lon_deg = number(o["lon_deg"], "/origin/lon_deg", -180.0, 180.0);
        if (o.contains("height_m"))
            r.origin_height_m = number(o["height_m"], "/origin/height_m", -500.0, 9000.0);
    }
    if (!j.contains("waypoints")) fail("/waypoints", "missing");
    const json& wps = j["waypoints"];
    if (!wps.is_array() || wps.size() < 2) fail("/waypoints", "must be an array of at least two waypoints");
    for (size_t i = 0; i < wps.size(); ++i) {
        const std::string w = "/waypoints/" + std::to_string(i);
        Waypoint wp;
        bool stairs_given = false;
        if (wps[i].is_array()) {
            vec(wps[i], w, 3, wp.enu_m);
        } else {
            check_keys(wps[i], w, {"enu_m", "stairs", "outdoor", "still_s", "gnss"});
            if (!wps[i].contains("enu_m")) fail(w + "/enu_m", "missing");
            vec(wps[i]["enu_m"], w + "/enu_m", 3, wp.enu_m);
            if (wps[i].contains("stairs"))
                wp.stairs = boolean(wps[i]["stairs"], w + "/stairs"), stairs_given = true;
            if (wps[i].contains("outdoor")) wp.outdoor = boolean(wps[i]["outdoor"], w + "/outdoor");
            if (wps[i].contains("still_s"))
                wp.still_s = number(wps[i]["still_s"], w + "/still_s", 0.0, 3600.0);
            if (wps[i].contains("gnss")) {
                wp.gnss = parse_gnss(wps[i]["gnss"], w + "/gnss");
                wp.gnss_given = true;
            }
        }
        if (i > 0 && !stairs_given) wp.stairs = std::fabs(wp.enu_m[2] - r.waypoints.back().enu_m[2]) > 1e-6;
        if (i > 0 && !wp.stairs && std::fabs(wp.enu_m[2] - r.waypoints.back().enu_m[2]) > 1e-6) {
            const double run = std::hypot(wp.enu_m[0] - r.waypoints.back().enu_m[0],
                                          wp.enu_m[1] - r.waypoints.back().enu_m[1]);
            if (std::fabs(wp.enu_m[2] - r.waypoints.back().enu_m[2]) > 0.15 * run)
                fail(w + "/stairs", "a ramp steeper than 15 % must be stairs");
        }
        r.waypoints.push_back(wp);
    }
    if (j.contains("mag_disturbances")) {
        const json& md = j["mag_disturbances"];
        if (!md.is_array()) fail("/mag_disturbances", "must be an array");
        for (size_t i = 0; i < md.size(); ++i) {
            const std::string w = "/mag_disturbances/" + std::to_string(i);
            check_keys(md[i], w, {"center_enu_m", "radius_m", "field_ut"});
            MagDisturbance d;
            if (!md[i].contains("center_enu_m")) fail(w + "/center_enu_m", "missing");
            if (!md[i].contains("field_ut")) fail(w + "/field_ut", "missing");
            vec(md[i]["center_enu_m"], w + "/center_enu_m", 3, d.center_enu_m);
            vec(md[i]["field_ut"], w + "/field_ut", 3, d.field_ut);
            if (md[i].contains("radius_m"))
                d.radius_m = number(md[i]["radius_m"], w + "/radius_m", 0.05, 100.0);
            r.mag_disturbances.push_back(d);
        }
    }
    if (j.contains("walls")) {
        const json& ws = j["walls"];
        if (!ws.is_array()) fail("/walls", "must be an array");
        for (size_t i = 0; i < ws.size(); ++i) {
            const std::string w = "/walls/" + std::to_string(i);
            check_keys(ws[i], w, {"floor", "points_enu_m"});
            Wall wall;
            if (ws[i].contains("floor")) {
                if (!ws[i]["floor"].is_number_integer()) fail(w + "/floor", "must be an integer");
                wall.floor = ws[i]["floor"].get<int>();
            }
            if (!ws[i].contains("points_enu_m") || !ws[i]["points_enu_m"].is_array() ||
                ws[i]["points_enu_m"].size() < 2)
                fail(w + "/points_enu_m", "must be an array of at least two [x, y] points");
            for (size_t k = 0; k < ws[i]["points_enu_m"].size(); ++k) {
                double xy[2];
                vec(ws[i]["points_enu_m"][k], w + "/points_enu_m/" + std::to_string(k), 2, xy);
                wall.points_enu_m.push_back({xy[0], xy[1]});
            }
            r.walls.push_back(std::move(wall));
        }
    }
    if (j.contains("gnss_jumps")) {
        const json& gj = j["gnss_jumps"];
        if (!gj.is_array()) fail("/gnss_jumps", "must be an array");
        for (size_t i = 0; i < gj.size(); ++i) {
            const std::string w = "/gnss_jumps/" + std::to_string(i);
            check_keys(gj[i], w, {"t_s", "duration_s", "offset_enu_m"});
            GnssJump jump;
            for (const char* key : {"t_s", "duration_s", "offset_enu_m"})
                if (!gj[i].contains(key)) fail(w + "/" + key, "missing");
            jump.t_s = number(gj[i]["t_s"], w + "/t_s", 0.0, 1e6);
            jump.duration_s = number(gj[i]["duration_s"], w + "/duration_s", 0.0, 1e6);
            vec(gj[i]["offset_enu_m"], w + "/offset_enu_m", 3, jump.offset_enu_m);
            r.gnss_jumps.push_back(jump);
        }
    }
    return r;
}

json route_to_json(const Route& r) {
    json j;
    j["format"] = "pednav-route/1";
    j["name"] = r.name;
    j["description"] = r.description;
    j["speed_mps"] = r.speed_mps;
    j["step_length_m"] = r.step_length_m;
    j["stance_fraction"] = r.stance_fraction;
    j["stair_rise_m"] = r.stair_rise_m;
    j["stair_run_m"] = r.stair_run_m;
    j["stairs_step_period_s"] = r.stairs_step_period_s;
    j["floor_height_m"] = r.floor_height_m;
    j["start_still_s"] = r.start_still_s;
    j["end_still_s"] = r.end_still_s;
    j["origin"] = {
        {"lat_deg", r.origin_lat_deg}, {"lon_deg", r.origin_lon_deg}, {"height_m", r.origin_height_m}};
    j["waypoints"] = json::array();
    for (const Waypoint& w : r.waypoints) {
        json wj = {{"enu_m", {w.enu_m[0], w.enu_m[1], w.enu_m[2]}},
                   {"stairs", w.stairs},
                   {"outdoor", w.outdoor},
                   {"still_s", w.still_s}};
        if (w.gnss_given) wj["gnss"] = gnss_to_json(w.gnss);  // absent = the default: route.json unchanged
        j["waypoints"].push_back(wj);
    }
    j["mag_disturbances"] = json::array();
    for (const MagDisturbance& d : r.mag_disturbances)
        j["mag_disturbances"].push_back(
            {{"center_enu_m", {d.center_enu_m[0], d.center_enu_m[1], d.center_enu_m[2]}},
             {"radius_m", d.radius_m},
             {"field_ut", {d.field_ut[0], d.field_ut[1], d.field_ut[2]}}});
    j["walls"] = json::array();
    for (const Wall& w : r.walls) {
        json pts = json::array();
        for (const auto& p : w.points_enu_m) pts.push_back({p[0], p[1]});
        j["walls"].push_back({{"floor", w.floor}, {"points_enu_m", pts}});
    }
    if (!r.gnss_jumps.empty()) {
        j["gnss_jumps"] = json::array();
        for (const GnssJump& g : r.gnss_jumps)
            j["gnss_jumps"].push_back({{"t_s", g.t_s},
                                       {"duration_s", g.duration_s},
                                       {"offset_enu_m", {g.offset_enu_m[0], g.offset_enu_m[1], g.offset_enu_m[2]}}});
    }
    return j;
}

double route_length_m(const Route& r) {
    double len = 0.0;
    for (size_t i = 1; i < r.waypoints.size(); ++i)
        len += std::hypot(r.waypoints[i].enu_m[0] - r.waypoints[i - 1].enu_m[0],
                          r.waypoints[i].enu_m[1] - r.waypoints[i - 1].enu_m[1]);
    return len;
}

}  // namespace pednav::sim
