#include "foot_eval.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <pednav_io/sensor_log.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::foot_eval {

namespace {
nlohmann::json load_json(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    std::string text = ss.str();
    // The ipol metadata writes a missing height as a bare NaN.
    for (size_t p = text.find("NaN"); p != std::string::npos; p = text.find("NaN", p)) text.replace(p, 3, "null");
    return nlohmann::json::parse(text);
}
double hypot2(const double* a, const double* b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }
}  // namespace

std::string data_dir() { return PEDNAV_SHARED_DATA_DIR; }

const double kKorogluGyroRangeRadps = 500.0 * M_PI / 180.0;

std::string foot_config(const nlohmann::json& patch) {
    nlohmann::json doc = load_json(std::string(PEDNAV_SOURCE_DIR) + "/configs/foot.json");
    // Another detector plugin starts from its own defaults, not the preset's params.
    const nlohmann::json::json_pointer det("/pipelines/foot/step_detector");
    if (patch.contains(det / "plugin") && patch[det / "plugin"] != doc[det / "plugin"])
        doc[det / "params"] = nlohmann::json::object();
    doc.merge_patch(patch);
    return doc.dump();
}

std::string koroglu_config(const nlohmann::json& patch) {
    // The 3DM-GX5-25 of these walks is set to +-500 deg/s and clips in brisk
    // swings: tell the attitude estimator the sensor's range, unless the patch
    // sets one itself (0 = the repair off, to measure without it).
    nlohmann::json p = patch;
    const nlohmann::json::json_pointer range("/pipelines/foot/attitude_estimator/params/gyro_range_radps");
    if (!p.contains(range)) p[range] = kKorogluGyroRangeRadps;
    return foot_config(p);
}

nlohmann::json detector_patch(const std::string& which) {
    nlohmann::json p = nlohmann::json::object();
    if (which == "multicondition") {
        p["pipelines"]["foot"]["step_detector"] = {{"plugin", "org.pednav.foot.stance.multicondition"},
                                                   {"params", nlohmann::json::object()}};
    } else if (which != "shoe") {
        throw std::runtime_error("unknown detector '" + which + "' (shoe or multicondition)");
    }
    return p;
}

nlohmann::json ekf_patch(const nlohmann::json& params) {
    nlohmann::json p;
    p["pipelines"]["foot"]["position_filter"]["params"] = params;
    return p;
}

namespace {
// Replays a read log through `config_json` at the log's IMU rate.
ReplayResult run_log(const io::SensorLog& log, const std::string& config_json, const std::string& what,
                     double* rate_hz = nullptr) {
    auto doc = nlohmann::json::parse(config_json);
    const io::StreamInfo* s = log.stream("accel");
    const double rate = s ? s->median_rate_hz : 0.0;
    if (rate_hz) *rate_hz = rate;
    doc["imu_rate_hz"] = rate;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = {PEDNAV_PLUGIN_OUTPUT_DIR};
    ReplayResult r = replay(o, io::merged_records(log));
    if (!r.error.empty()) throw std::runtime_error(what + ": " + r.error);
    return r;
}
}  // namespace

ReplayResult run_file(const std::string& path, const std::string& config_json, double* rate_hz) {
    return run_log(io::read_sensor_file(path), config_json, path, rate_hz);
}

Stats stats_of(const std::vector<double>& v) {
    Stats s;
    s.n = v.size();
    if (v.empty()) return s;
    s.min = *std::min_element(v.begin(), v.end());
    s.max = *std::max_element(v.begin(), v.end());
    double sum = 0;
    for (double x : v) sum += x;
    s.mean = sum / v.size();
    double ss = 0;
    for (double x : v) ss += (x - s.mean) * (x - s.mean);
    s.sd = v.size() > 1 ? std::sqrt(ss / (v.size() - 1)) : 0.0;
    s.final = v.back();
    return s;
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

XioScore score_xio(const std::string& name, const std::string& config_json) {
    XioScore sc;
    sc.name = name;
    const ReplayResult r = run_file(data_dir() + "/xio-gait-ngimu/" + name + ".csv", config_json);
    if (r.positions.empty()) throw std::runtime_error("xio " + name + ": no positions");
    const auto& a = r.positions.front();
    const auto& b = r.positions.back();
    sc.closure_h_m = hypot2(a.pos_enu_m, b.pos_enu_m);
    sc.closure_m = std::hypot(sc.closure_h_m, b.pos_enu_m[2] - a.pos_enu_m[2]);
    sc.distance_m = stride_path_m(r);
    sc.closure_pct = sc.distance_m > 0 ? 100.0 * sc.closure_m / sc.distance_m : 100.0;
    sc.strides = r.strides.size();
    return sc;
}

ClipScore score_xio_clipped(const std::string& name, const std::string& config_json, double clip_radps,
                            bool tell_range) {
    ClipScore sc;
    io::SensorLog log = io::read_sensor_file(data_dir() + "/xio-gait-ngimu/" + name + ".csv");
    const ReplayResult ref = run_log(log, config_json, name);
    for (auto& r : log.imu)
        for (double& g : r.gyro_radps)
            if (std::abs(g) > clip_radps) {
                g = std::copysign(clip_radps, g);
                ++sc.clipped_samples;
            }
    auto doc = nlohmann::json::parse(config_json);
    if (tell_range) doc["pipelines"]["foot"]["attitude_estimator"]["params"]["gyro_range_radps"] = clip_radps;
    const ReplayResult r = run_log(log, doc.dump(), name + " clipped");
    sc.strides = r.strides.size();
    sc.strides_unclipped = ref.strides.size();
    const size_t n = std::min(sc.strides, sc.strides_unclipped);
    double ex = 0, ey = 0, eh = 0, sum_p = 0, sum_h = 0;
    for (size_t i = 0; i < n; ++i) {
        ex += r.strides[i].displacement_enu_m[0] - ref.strides[i].displacement_enu_m[0];
        ey += r.strides[i].displacement_enu_m[1] - ref.strides[i].displacement_enu_m[1];
        eh += r.strides[i].heading_change_rad - ref.strides[i].heading_change_rad;
        sum_p += ex * ex + ey * ey;
        const double dh = std::remainder(eh, 2.0 * M_PI) * 180.0 / M_PI;
        sum_h += dh * dh;
    }
    if (n) {
        sc.footprint_rms_m = std::sqrt(sum_p / n);
        sc.heading_rms_deg = std::sqrt(sum_h / n);
    }
    return sc;
}

KorogluScore score_koroglu(int n, const std::string& config_json) {
    KorogluScore sc;
    sc.name = "SensorConnectData_" + std::to_string(n);
    const std::string base = data_dir() + "/koroglu-foot-gcp/" + sc.name;
    // Ground truth: stride_number, gcp_x_m, gcp_y_m, stride_index_200Hz, timestamp_s.
    std::ifstream f(base + "_gcp.csv");
    if (!f) throw std::runtime_error("cannot open " + base + "_gcp.csv");
    std::string line;
    std::vector<double> gx, gy, gt;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#' || line[0] == 's') continue;
        std::stringstream ss(line);
        std::string cell;
        std::vector<double> v;
        while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
        if (v.size() < 5) continue;
        gx.push_back(v[1]);
        gy.push_back(v[2]);
        gt.push_back(v[4]);
    }
    sc.footprints = gx.size() - 1;
    for (size_t i = 1; i < gx.size(); ++i) sc.path_m += std::hypot(gx[i] - gx[i - 1], gy[i] - gy[i - 1]);

    const ReplayResult r = run_file(base + ".csv", config_json);
    sc.strides = r.strides.size();
    // Estimated footprint: the position at the end of each annotated stance,
    // relative to the one of stride 0.
    std::vector<double> ex, ey;
    for (size_t i = 0; i < gt.size(); ++i) {
        const auto& p = position_at(r, gt[i]);
        ex.push_back(p.pos_enu_m[0]);
        ey.push_back(p.pos_enu_m[1]);
    }
    for (size_t i = 1; i < ex.size(); ++i) sc.est_path_m += std::hypot(ex[i] - ex[i - 1], ey[i] - ey[i - 1]);
    const double x0 = ex[0], y0 = ey[0];
    for (size_t i = 0; i < ex.size(); ++i) {
        ex[i] -= x0;
        ey[i] -= y0;
    }
    // One rotation fitted on the first 5 strides (footprints 0..5), least squares.
    double sdot = 0, scross = 0;
    for (size_t i = 1; i <= std::min<size_t>(5, ex.size() - 1); ++i) {
        sdot += ex[i] * gx[i] + ey[i] * gy[i];
        scross += ex[i] * gy[i] - ey[i] * gx[i];
    }
    const double ang = std::atan2(scross, sdot), c = std::cos(ang), s = std::sin(ang);
    std::vector<double> err;
    for (size_t i = 0; i < ex.size(); ++i) {
        const double x = c * ex[i] - s * ey[i], y = s * ex[i] + c * ey[i];
        sc.dx.push_back(x - gx[i]);
        sc.dy.push_back(y - gy[i]);
        err.push_back(std::hypot(x - gx[i], y - gy[i]));
    }
    sc.err_m = stats_of(err);
    sc.mean_pct = 100.0 * sc.err_m.mean / sc.path_m;
    return sc;
}

IpolScore score_ipol(const std::string& trial, const std::string& foot, const std::string& config_json) {
    IpolScore sc;
    sc.name = trial + "_" + foot;
    const std::string base = data_dir() + "/ipol-gait-waist-feet/" + trial;
    const nlohmann::json meta = load_json(base + ".json");
    const ReplayResult r = run_file(base + "_" + foot + ".txt", config_json);
    if (r.positions.empty()) throw std::runtime_error("ipol " + sc.name + ": no positions");
    // Out: from the start to the turnaround (the point farthest from the
    // start); back: from there to the end. The walker stands still at both ends.
    const double* p0 = r.positions.front().pos_enu_m;
    size_t far = 0;
    double far_d = 0;
    for (size_t i = 0; i < r.positions.size(); ++i) {
        const double d = hypot2(r.positions[i].pos_enu_m, p0);
        if (d > far_d) {
            far_d = d;
            far = i;
        }
    }
    sc.leg_out_m = far_d;
    sc.leg_back_m = hypot2(r.positions[far].pos_enu_m, r.positions.back().pos_enu_m);
    sc.strides = r.strides.size();
    sc.footsteps = meta.at(foot == "lf" ? "LeftFootEvents" : "RightFootEvents").size();
    // The dataset's own legs: out from the walk's start to the U-turn's, back
    // from the U-turn's end to the walk's end (annotated sample indices, 100 Hz).
    const auto& walk = meta.at("TrialBoundaries");
    const auto& turn = meta.at("UTurnBoundaries");
    const auto at = [&](const nlohmann::json& index) { return position_at(r, index.get<double>() / 100.0).pos_enu_m; };
    sc.annotated_out_m = hypot2(at(walk[0]), at(turn[0]));
    sc.annotated_back_m = hypot2(at(turn[1]), at(walk[1]));
    return sc;
}

SimScore score_sim(const SimCase& c, const std::string& config_json) {
    sim::SimOptions so;
    so.rate_hz = c.rate_hz;
    so.sensor_errors = c.sensor_errors;
    so.seed = c.seed;
    so.with_gnss = false;
    so.with_baro = false;
    for (int i = 0; i < 3; ++i) so.mounting_rpy_deg[i] = c.mounting_rpy_deg[i];
    sim::ImuErrorModel& m = so.imu;
    for (double* v : {&m.accel_noise_mps2_per_rthz, &m.accel_bias_mps2, &m.accel_bias_rw_mps2_per_rts, &m.accel_scale,
                      &m.gyro_noise_radps_per_rthz, &m.gyro_bias_radps, &m.gyro_bias_rw_radps_per_rts, &m.gyro_scale})
        *v *= c.error_scale;
    m.accel_bias_rw_mps2_per_rts *= c.accel_bias_walk_scale;
    if (!c.gyro_scale_errors) m.gyro_scale = 0.0;
    so.heel_strike_g = c.gait.heel_strike_g;
    sim::Route route = sim::builtin_route(c.route);
    if (c.gait.speed_mps > 0) route.speed_mps = c.gait.speed_mps;
    if (c.gait.step_length_m > 0) route.step_length_m = c.gait.step_length_m;
    if (c.gait.stance_fraction > 0) route.stance_fraction = c.gait.stance_fraction;
    const sim::SimOutput out = sim::simulate(route, so);
    auto doc = nlohmann::json::parse(config_json);
    doc["imu_rate_hz"] = c.rate_hz;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = {PEDNAV_PLUGIN_OUTPUT_DIR};
    // The truth's start point and walking heading.
    const auto& t0 = out.truth.front();
    for (int i = 0; i < 3; ++i) o.start_enu_m[i] = t0.pos_enu_m[i];
    const ReplayResult r = replay(o, out.records());
    if (!r.error.empty()) throw std::runtime_error("sim " + c.route + ": " + r.error);
    if (r.positions.empty()) throw std::runtime_error("sim " + c.route + ": no positions");
    SimScore sc;
    sc.distance_m = out.distance_m;
    sc.strides = r.strides.size();
    sc.true_strides = out.step_times_s.size();
    for (const auto& s : r.strides) (s.stride_class == PN_STRIDE_CLASS_LEVEL ? sc.level : sc.stairs)++;
    const auto& a = r.positions.front();
    const auto& b = r.positions.back();
    sc.closure_m = hypot2(a.pos_enu_m, b.pos_enu_m);
    sc.closure_pct = 100.0 * sc.closure_m / sc.distance_m;
    // Align the estimate to the truth at the first output (heading included:
    // the attitude estimator does not know the walking direction).
    size_t k = 0;
    while (k < out.truth.size() && out.truth[k].t_s * 1e9 < a.header.t_ns - 1000) ++k;
    const auto& ta = out.truth[std::min(k, out.truth.size() - 1)];
    double sum_z = 0;
    size_t n = 0, j = k;
    for (const auto& p : r.positions) {
        while (j + 1 < out.truth.size() && out.truth[j].t_s * 1e9 < p.header.t_ns - 1000) ++j;
        const auto& tj = out.truth[j];
        const double ez = (p.pos_enu_m[2] - a.pos_enu_m[2]) - (tj.pos_enu_m[2] - ta.pos_enu_m[2]);
        sc.final_err_z_m = ez;
        if (!tj.stance) continue;  // scored where the foot stands, like the paper's reference points
        sum_z += std::abs(ez);
        ++n;
    }
    sc.mean_err_z_m = n ? sum_z / n : 0.0;
    sc.final_err_z_m = std::abs(sc.final_err_z_m);
    // Horizontal error after fitting the start heading (one rotation about the start).
    double sdot = 0, scross = 0;
    j = k;
    std::vector<std::array<double, 4>> pairs;
    for (const auto& p : r.positions) {
        while (j + 1 < out.truth.size() && out.truth[j].t_s * 1e9 < p.header.t_ns - 1000) ++j;
        const double ex = p.pos_enu_m[0] - a.pos_enu_m[0], ey = p.pos_enu_m[1] - a.pos_enu_m[1];
        const double gx = out.truth[j].pos_enu_m[0] - ta.pos_enu_m[0], gy = out.truth[j].pos_enu_m[1] - ta.pos_enu_m[1];
        sdot += ex * gx + ey * gy;
        scross += ex * gy - ey * gx;
        pairs.push_back({ex, ey, gx, gy});
    }
    const double ang = std::atan2(scross, sdot), cs = std::cos(ang), sn = std::sin(ang);
    for (const auto& q : pairs)
        sc.max_err_h_m = std::max(sc.max_err_h_m, std::hypot(cs * q[0] - sn * q[1] - q[2], sn * q[0] + cs * q[1] - q[3]));
    return sc;
}

const std::vector<Gait>& sweep_gaits() {
    static const std::vector<Gait> gaits = {{"slow", 0.8, 0.55, 0.36, 0.0},
                                            {"normal", 1.3, 0.7, 0.28, 0.0},
                                            {"brisk", 1.9, 0.85, 0.2, 2.0},
                                            {"jog", 3.0, 1.1, 0.12, 3.0}};
    return gaits;
}

}  // namespace pednav::foot_eval
