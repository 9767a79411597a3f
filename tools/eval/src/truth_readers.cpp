// SPDX-License-Identifier: Apache-2.0
#include <pednav_eval/truth_readers.hpp>

#include <sys/stat.h>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_geodesy/enu.hpp>
#include <pednav_io/origin.hpp>
#include <pednav_sim/simulate.hpp>

#include "fields.hpp"

namespace pednav::eval {

using detail::number;
using io::find_column;

namespace {

std::ifstream open(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    return in;
}

bool is_dir(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool exists(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}

std::string dir_of(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
}

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// JSON as written by Python's json module: bare NaN / Infinity (ipol's Height
// of subject 10) become null before parsing.
nlohmann::json read_json(const std::string& path) {
    std::ifstream in = open(path);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string raw = ss.str();
    std::string text;
    bool in_string = false;
    for (size_t i = 0; i < raw.size(); ++i) {
        const char c = raw[i];
        if (c == '"' && (i == 0 || raw[i - 1] != '\\')) in_string = !in_string;
        if (!in_string && raw.compare(i, 3, "NaN") == 0) {
            text += "null";
            i += 2;
        } else if (!in_string && raw.compare(i, 9, "-Infinity") == 0) {
            text += "null";
            i += 8;
        } else if (!in_string && raw.compare(i, 8, "Infinity") == 0) {
            text += "null";
            i += 7;
        } else {
            text += c;
        }
    }
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

double json_number(const nlohmann::json& j, const std::string& key, const std::string& path) {
    if (!j.contains(key) || !j[key].is_number())
        throw std::runtime_error(path + ": missing number '" + key + "'");
    return j[key].get<double>();
}

// Horizontal length of the polyline through the points.
double path_length_m(const std::vector<TruthPoint>& points) {
    double d = 0.0;
    for (size_t i = 1; i < points.size(); ++i)
        d += std::hypot(points[i].x_m - points[i - 1].x_m, points[i].y_m - points[i - 1].y_m);
    return d;
}

}  // namespace

Truth sim_truth(const std::vector<TruthPoint>& rows, std::vector<double> step_times_s, double period_s) {
    if (rows.empty()) throw std::runtime_error("simulated truth: no rows");
    Truth t;
    t.kind = TruthKind::simulated;
    double next_t = -1e300;
    const double dist = path_length_m(rows);
    for (const TruthPoint& p : rows) {
        if (p.t_s >= next_t - 1e-9) {
            t.points.push_back(p);
            next_t = p.t_s + period_s;
        }
    }
    const TruthPoint &a = rows.front(), &last = rows.back();
    if (t.points.back().t_s != last.t_s) t.points.push_back(last);
    t.step_count = static_cast<int>(step_times_s.size());
    t.step_times_s = std::move(step_times_s);
    t.distance_m = dist;
    t.closed_loop =
        std::hypot(last.x_m - a.x_m, last.y_m - a.y_m) < 0.05 && std::fabs(last.z_m - a.z_m) < 0.05;
    if (t.closed_loop) {
        t.loop_start_s = a.t_s;
        t.loop_end_s = last.t_s;
        t.loop_length_m = dist;
    }
    return t;
}

Truth sim_truth(const sim::SimOutput& out, const sim::Route& route, double period_s) {
    std::vector<TruthPoint> rows;
    rows.reserve(out.truth.size());
    for (const sim::TruthSample& s : out.truth) {
        TruthPoint p;
        p.t_s = s.t_s;
        p.x_m = s.pos_enu_m[0];
        p.y_m = s.pos_enu_m[1];
        p.z_m = s.pos_enu_m[2];
        p.floor = s.floor;
        p.has_floor = true;
        p.heading_deg = s.heading_deg;
        rows.push_back(p);
    }
    Truth t = sim_truth(rows, out.step_times_s, period_s);
    t.name = route.name;
    for (const sim::Wall& w : route.walls) t.walls.push_back({w.floor, w.points_enu_m});
    return t;
}

Truth read_sim_truth(const std::string& path, double period_s) {
    std::ifstream in = open(path);
    std::string line;
    std::vector<std::string> header;
    int ct = -1, cx = -1, cy = -1, cz = -1, cstep = -1, cfloor = -1, chead = -1;
    size_t n = 0;
    std::vector<TruthPoint> rows;
    std::vector<double> step_times_s;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string_view> f = io::split(line, ',');
        if (header.empty()) {
            header = detail::to_strings(f);
            ct = find_column(header, "t"), cx = find_column(header, "x"), cy = find_column(header, "y"),
            cz = find_column(header, "z");
            cstep = find_column(header, "step"), cfloor = find_column(header, "floor"),
            chead = find_column(header, "heading_deg");
            if (ct < 0 || cx < 0 || cy < 0 || cz < 0)
                throw std::runtime_error(path + ": not a pednav sim truth file");
            continue;
        }
        if (f.size() < header.size())
            throw std::runtime_error(path + ":" + std::to_string(n) + ": short row");
        TruthPoint p;
        p.t_s = number(f[ct], path, n, "t");
        p.x_m = number(f[cx], path, n, "x");
        p.y_m = number(f[cy], path, n, "y");
        p.z_m = number(f[cz], path, n, "z");
        if (cfloor >= 0) p.floor = static_cast<int>(number(f[cfloor], path, n, "floor")), p.has_floor = true;
        if (chead >= 0) p.heading_deg = number(f[chead], path, n, "heading_deg");
        if (cstep >= 0 && number(f[cstep], path, n, "step") != 0.0) step_times_s.push_back(p.t_s);
        rows.push_back(p);
    }
    if (rows.empty()) throw std::runtime_error(path + ": no truth rows");
    Truth t = sim_truth(rows, std::move(step_times_s), period_s);
    t.name = path;
    const std::string route = dir_of(path) + "/route.json";
    if (exists(route)) {
        const nlohmann::json r = read_json(route);
        if (r.contains("walls") && r["walls"].is_array())
            for (const auto& w : r["walls"]) {
                WallLine wall_line;
                wall_line.floor = w.value("floor", 0);
                for (const auto& p : w.at("points_enu_m"))
                    wall_line.points_m.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
                t.walls.push_back(std::move(wall_line));
            }
    }
    return t;
}

Truth read_koroglu_gcp(const std::string& path) {
    std::ifstream in = open(path);
    Truth t;
    t.kind = TruthKind::footprints;
    t.name = path;
    std::string line;
    std::vector<std::string> header;
    int cx = -1, cy = -1, ct = -1;
    size_t n = 0;
    while (std::getline(in, line)) {
        ++n;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string_view> f = io::split(line, ',');
        if (header.empty()) {
            header = detail::to_strings(f);
            cx = find_column(header, "gcp_x_m"), cy = find_column(header, "gcp_y_m"),
            ct = find_column(header, "timestamp_s");
            if (cx < 0 || cy < 0 || ct < 0)
                throw std::runtime_error(path + ": expected gcp_x_m, gcp_y_m, timestamp_s columns");
            continue;
        }
        if (f.size() < header.size())
            throw std::runtime_error(path + ":" + std::to_string(n) + ": short row");
        TruthPoint p;
        p.t_s = number(f[ct], path, n, "timestamp_s");
        p.x_m = number(f[cx], path, n, "gcp_x_m");
        p.y_m = number(f[cy], path, n, "gcp_y_m");
        t.points.push_back(p);
    }
    if (t.points.size() < 2) throw std::runtime_error(path + ": fewer than two footprints");
    t.step_count = static_cast<int>(t.points.size()) - 1;
    t.distance_m = path_length_m(t.points);
    return t;
}

Truth read_humolire(const std::string& dir) {
    const std::string kp_path = dir + "/keypoints.json";
    const nlohmann::json kp = read_json(kp_path);
    Truth t;
    t.kind = TruthKind::landmarks;
    t.name = dir;
    if (!kp.contains("starting_position"))
        throw std::runtime_error(kp_path + ": missing 'starting_position'");
    t.start_x_m = json_number(kp["starting_position"], "x", kp_path);
    t.start_y_m = json_number(kp["starting_position"], "y", kp_path);
    // starting_heading: degrees counter-clockwise from the map's x axis (upstream: x += L cos, y += L sin).
    const double h = json_number(kp, "starting_heading", kp_path);
    t.start_heading_deg = std::fmod(90.0 - h + 720.0, 360.0);
    const int count = static_cast<int>(json_number(kp, "count", kp_path));
    std::vector<std::array<double, 2>> marks;
    for (int k = 0; k < count; ++k) {
        const std::string key = std::to_string(k);
        if (!kp.contains(key)) throw std::runtime_error(kp_path + ": missing landmark '" + key + "'");
        marks.push_back({json_number(kp[key], "x", kp_path), json_number(kp[key], "y", kp_path)});
    }
    // references.txt: header lines, then "t 0.0 0.0" per landmark.
    const std::string ref_path = dir + "/references.txt";
    std::ifstream in = open(ref_path);
    std::string line;
    std::vector<double> times;
    while (std::getline(in, line)) {
        std::istringstream ss(line);
        double a = 0.0, b = 0.0, c = 0.0;
        if (ss >> a >> b >> c) times.push_back(a);
    }
    if (times.size() != marks.size())
        throw std::runtime_error(ref_path + ": " + std::to_string(times.size()) + " reference times for " +
                                 std::to_string(marks.size()) + " landmarks");
    double d = 0.0, px = t.start_x_m, py = t.start_y_m;
    for (size_t k = 0; k < marks.size(); ++k) {
        TruthPoint p;
        p.t_s = times[k];
        p.x_m = marks[k][0];
        p.y_m = marks[k][1];
        t.points.push_back(p);
        d += std::hypot(p.x_m - px, p.y_m - py);
        px = p.x_m;
        py = p.y_m;
    }
    t.distance_m = d;  // landmark polyline: a lower bound of the distance walked
    const std::string map = dir + "/../maps/map_data.json";
    if (exists(map)) {
        const nlohmann::json mj = read_json(map);
        // The walls' pixels have y down the image; the keypoints' metres y up
        // from its bottom edge, y_range[1] pixels down (as upstream's MapHandler).
        const double scale = mj.value("scale", 0.04);
        const double height_m = scale * mj.at("y_range").at(1).get<double>();
        for (const auto& link : mj.at("links")) {
            WallLine w;
            w.floor = link.value("layer", 0);
            w.points_m.push_back({scale * link.at("node0").at("x").get<double>(),
                                  height_m - scale * link.at("node0").at("y").get<double>()});
            w.points_m.push_back({scale * link.at("node1").at("x").get<double>(),
                                  height_m - scale * link.at("node1").at("y").get<double>()});
            t.walls.push_back(std::move(w));
        }
    }
    return t;
}

Truth read_ipin_posi(const std::string& path) {
    std::ifstream in = open(path);
    Truth t;
    t.kind = TruthKind::ipin_posi;
    t.name = path;
    std::string line;
    size_t n = 0;
    io::Origin origin;
    while (std::getline(in, line)) {
        ++n;
        if (line.rfind("POSI;", 0) != 0) continue;
        const std::vector<std::string_view> f = io::split(line, ';');
        if (f.size() < 6)
            throw std::runtime_error(path + ":" + std::to_string(n) + ": POSI needs t;counter;lat;lon;floor");
        const double time = number(f[1], path, n), lat = number(f[3], path, n), lon = number(f[4], path, n);
        // Local tangent plane about the first point.
        if (!origin.known) origin = io::Origin{lat, lon, 0.0, true, 0};
        double enu[3];
        geodesy::geodetic_to_enu(origin, lat, lon, 0.0, enu);
        TruthPoint p;
        p.t_s = time;
        p.x_m = enu[0];
        p.y_m = enu[1];
        p.floor = static_cast<int>(number(f[5], path, n));
        p.has_floor = true;
        t.points.push_back(p);
    }
    if (t.points.empty()) throw std::runtime_error(path + ": no POSI lines");
    return t;
}

Truth make_loop_truth(double length_m) {
    Truth t;
    t.kind = TruthKind::loop;
    t.name = "closed loop";
    t.closed_loop = true;
    t.loop_length_m = length_m;
    t.distance_m = length_m;
    return t;
}

Truth read_ipol_steps(const std::string& path, double rate_hz, double leg_length_m, const std::string& feet,
                      bool whole_recording) {
    if (feet != "both" && feet != "left" && feet != "right")
        throw std::runtime_error("ipol steps: feet must be both, left or right");
    const nlohmann::json j = read_json(path);
    Truth t;
    t.kind = TruthKind::step_events;
    t.name = path;
    try {
        const double tb0 = j.at("TrialBoundaries").at(0).get<double>(),
                     tb1 = j.at("TrialBoundaries").at(1).get<double>();
        const double ut0 = j.at("UTurnBoundaries").at(0).get<double>(),
                     ut1 = j.at("UTurnBoundaries").at(1).get<double>();
        for (const char* key : {"LeftFootEvents", "RightFootEvents"}) {
            if ((feet == "left" && key[0] != 'L') || (feet == "right" && key[0] != 'R')) continue;
            for (const auto& ev : j.at(key)) {
                const double end = ev.at(1).get<double>();
                if (whole_recording || (ev.at(0).get<double>() >= tb0 && end <= tb1))
                    t.step_times_s.push_back(end / rate_hz);
            }
        }
        std::sort(t.step_times_s.begin(), t.step_times_s.end());
        t.step_count = static_cast<int>(t.step_times_s.size());
        t.legs.push_back({tb0 / rate_hz, ut0 / rate_hz, leg_length_m});
        t.legs.push_back({ut1 / rate_hz, tb1 / rate_hz, leg_length_m});
        t.distance_m = 2.0 * leg_length_m;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    return t;
}

double read_ipol_height_m(const std::string& path) {
    const nlohmann::json j = read_json(path);
    const auto it = j.find("Height");
    return it != j.end() && it->is_number() ? it->get<double>() / 100.0 : NAN;
}

Truth read_truth(const std::string& path, const std::string& kind_in) {
    std::string kind = kind_in;
    if (kind.rfind("loop", 0) == 0) {
        const size_t colon = kind.find(':');
        return make_loop_truth(colon == std::string::npos ? NAN : std::stod(kind.substr(colon + 1)));
    }
    if (kind == "auto") {
        if (is_dir(path) && exists(path + "/keypoints.json"))
            kind = "humolire";
        else if (is_dir(path) && exists(path + "/truth.csv"))
            return read_sim_truth(path + "/truth.csv");
        else if (ends_with(path, "_gcp.csv"))
            kind = "koroglu";
        else if (ends_with(path, ".json"))
            kind = "ipol";
        else {
            std::ifstream in = open(path);
            std::string line;
            kind = "ipin";
            while (std::getline(in, line))
                if (!line.empty() && line[0] != '#') {
                    if (line.rfind("t,x,y,z,qw", 0) == 0) kind = "sim";
                    break;
                }
        }
    }
    if (kind == "sim") return read_sim_truth(path);
    if (kind == "koroglu") return read_koroglu_gcp(path);
    if (kind == "humolire") return read_humolire(path);
    if (kind == "ipin") return read_ipin_posi(path);
    if (kind == "ipol") return read_ipol_steps(path);
    throw std::runtime_error("unknown truth kind '" + kind_in +
                             "' (sim, koroglu, humolire, ipin, loop[:LENGTH_M], ipol, auto)");
}

}  // namespace pednav::eval
