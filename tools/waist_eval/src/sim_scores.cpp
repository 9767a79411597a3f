// SPDX-License-Identifier: Apache-2.0
#include <pednav_waist_eval/sim_scores.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_geodesy/enu.hpp>
#include <pednav_sim/route.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::waist_eval {

namespace {
size_t truth_index(const sim::SimOutput& out, int64_t t_ns) {
    const double k = static_cast<double>(t_ns) * 1e-9 * out.rate_hz;
    const long i = std::lround(k);
    return static_cast<size_t>(std::clamp<long>(i, 0, static_cast<long>(out.truth.size()) - 1));
}
}  // namespace

ReplayResult run_sim_waist(const sim::SimOutput& out, const sim::Route& route, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs) {
    nlohmann::json doc = nlohmann::json::parse(config_json);
    doc["imu_rate_hz"] = out.rate_hz;
    doc["origin"] = {{"lat_deg", route.origin_lat_deg}, {"lon_deg", route.origin_lon_deg},
                     {"height_m", route.origin_height_m}};
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = plugin_dirs;
    ReplayResult r = replay(o, out.records());
    if (!r.error.empty()) throw std::runtime_error("simulated " + route.name + ": " + r.error);
    return r;
}

std::vector<OutputError> output_errors(const ReplayResult& r, const sim::SimOutput& out) {
    if (out.truth.empty()) throw std::runtime_error("simulated walk without truth");
    std::vector<double> walked(out.truth.size(), 0.0);
    for (size_t i = 1; i < out.truth.size(); ++i)
        walked[i] = walked[i - 1] + std::hypot(out.truth[i].pos_enu_m[0] - out.truth[i - 1].pos_enu_m[0],
                                               out.truth[i].pos_enu_m[1] - out.truth[i - 1].pos_enu_m[1]);
    std::vector<OutputError> errors;
    for (const pn_position_t& p : r.positions) {
        const size_t i = truth_index(out, p.header.t_ns);
        OutputError e;
        e.t_s = static_cast<double>(p.header.t_ns) * 1e-9;
        e.err_e_m = p.pos_enu_m[0] - out.truth[i].pos_enu_m[0];
        e.err_n_m = p.pos_enu_m[1] - out.truth[i].pos_enu_m[1];
        e.err_h_m = std::hypot(e.err_e_m, e.err_n_m);
        e.source = p.source;
        e.walked_m = walked[i];
        e.true_e_m = out.truth[i].pos_enu_m[0];
        e.true_n_m = out.truth[i].pos_enu_m[1];
        e.var_e_m2 = p.cov_enu_m2[0];
        e.var_n_m2 = p.cov_enu_m2[4];
        errors.push_back(e);
    }
    return errors;
}

StairsScore stairs_score(const ReplayResult& r, const sim::SimOutput& out) {
    StairsScore s;
    for (const pn_step_t& st : r.steps) {
        if (st.motion_mode == PN_STEP_MODE_STATIC) continue;
        const size_t i0 = truth_index(out, st.t_start_ns), i1 = truth_index(out, st.header.t_ns);
        const double dt = static_cast<double>(st.header.t_ns - st.t_start_ns) * 1e-9;
        if (!(dt > 0)) continue;
        const double vz = (out.truth[i1].pos_enu_m[2] - out.truth[i0].pos_enu_m[2]) / dt;
        const bool up = st.motion_mode == PN_STEP_MODE_UPSTAIRS, down = st.motion_mode == PN_STEP_MODE_DOWNSTAIRS;
        if (vz > 0.15) ++s.up_steps, s.up_labelled_up += up;
        else if (vz < -0.15) ++s.down_steps, s.down_labelled_down += down;
        else if (std::abs(vz) < 0.02) ++s.level_steps, s.level_labelled_stairs += up || down;
    }
    return s;
}

std::pair<double, double> longest_gnss_gap_s(const std::vector<pn_gnss_t>& fixes) {
    std::pair<double, double> gap{0, 0};
    for (size_t i = 1; i < fixes.size(); ++i) {
        const double a = static_cast<double>(fixes[i - 1].header.t_ns) * 1e-9,
                     b = static_cast<double>(fixes[i].header.t_ns) * 1e-9;
        if (b - a > gap.second - gap.first) gap = {a, b};
    }
    return gap;
}

Drift drift_in(const std::vector<OutputError>& errors, double t0, double t1) {
    const OutputError* ref = nullptr;
    for (const OutputError& e : errors)
        if (e.t_s <= t0) ref = &e;
    if (!ref) throw std::runtime_error("no output before the outage at " + std::to_string(t0) + " s");
    Drift d;
    // Displacements since the reference as complex numbers (x = E, y = N).
    std::vector<std::complex<double>> z, w;
    for (const OutputError& e : errors) {
        if (e.t_s <= t0 || e.t_s > t1) continue;
        d.max_m = std::max(d.max_m, std::hypot(e.err_e_m - ref->err_e_m, e.err_n_m - ref->err_n_m));
        d.walked_m = e.walked_m - ref->walked_m;
        const std::complex<double> zt(e.true_e_m - ref->true_e_m, e.true_n_m - ref->true_n_m);
        z.push_back(zt);
        w.push_back(zt + std::complex<double>(e.err_e_m - ref->err_e_m, e.err_n_m - ref->err_n_m));
    }
    std::complex<double> num = 0;
    double den = 0;
    for (size_t i = 0; i < z.size(); ++i) num += std::conj(z[i]) * w[i], den += std::norm(z[i]);
    if (den > 0 && std::abs(num) > 0) {
        const std::complex<double> a = num / den;
        d.scale_pct = 100.0 * (std::abs(a) - 1.0);
        // A counter-clockwise rotation in ENU is an azimuth decrease.
        d.rotation_deg = -std::arg(a) * 180.0 / M_PI;
        for (size_t i = 0; i < z.size(); ++i)
            d.max_without_scale_m = std::max(d.max_without_scale_m, std::abs(w[i] / std::abs(a) - z[i]));
    }
    return d;
}

double true_step_length_m(const sim::SimOutput& out, double t0_s, double t1_s) {
    std::vector<size_t> idx;
    for (double t : out.step_times_s)
        if (t > t0_s && t <= t1_s) idx.push_back(truth_index(out, static_cast<int64_t>(std::llround(t * 1e9))));
    if (idx.size() < 3) return NAN;
    double sum = 0;
    for (size_t k = 2; k < idx.size(); ++k)
        sum += std::hypot(out.truth[idx[k]].pos_enu_m[0] - out.truth[idx[k - 2]].pos_enu_m[0],
                          out.truth[idx[k]].pos_enu_m[1] - out.truth[idx[k - 2]].pos_enu_m[1]);
    return 0.5 * sum / static_cast<double>(idx.size() - 2);
}

double stride_length_error_pct(const ReplayResult& r, const sim::SimOutput& out, double t0_s, double t1_s) {
    double learnt_m = 0, true_m = 0;
    for (const pn_stride_t& st : r.strides) {
        const double t_s = static_cast<double>(st.header.t_ns) * 1e-9;
        if (t_s <= t0_s || t_s > t1_s) continue;
        const sim::TruthSample &a = out.truth[truth_index(out, st.t_start_ns)],
                               &b = out.truth[truth_index(out, st.header.t_ns)];
        learnt_m += st.length_m;
        true_m += std::hypot(b.pos_enu_m[0] - a.pos_enu_m[0], b.pos_enu_m[1] - a.pos_enu_m[1]);
    }
    return true_m > 0 ? 100.0 * (learnt_m / true_m - 1.0) : NAN;
}

double mean_error_of(const std::vector<OutputError>& errors, int source, int* count) {
    double s = 0;
    int n = 0;
    for (const OutputError& e : errors)
        if (e.source == source) s += e.err_h_m, ++n;
    if (count) *count = n;
    return n ? s / n : NAN;
}

double mean_h_accuracy_m(const std::vector<pn_gnss_t>& fixes) {
    double s = 0;
    for (const pn_gnss_t& g : fixes) s += g.h_accuracy_m;
    return fixes.empty() ? NAN : s / static_cast<double>(fixes.size());
}

double mean_nees_per_axis_of(const std::vector<OutputError>& errors, int source) {
    double s = 0;
    int n = 0;
    for (const OutputError& e : errors)
        if (e.source == source && e.var_e_m2 > 0 && e.var_n_m2 > 0)
            s += e.err_e_m * e.err_e_m / e.var_e_m2 + e.err_n_m * e.err_n_m / e.var_n_m2, n += 2;
    return n ? s / n : NAN;
}

double mean_fix_error_m(const sim::SimOutput& out, const sim::Route& route, double t0_s, double t1_s) {
    const geodesy::GeodeticPoint origin{route.origin_lat_deg, route.origin_lon_deg, route.origin_height_m};
    double s = 0;
    int n = 0;
    for (const pn_gnss_t& g : out.gnss) {
        const double t_s = static_cast<double>(g.header.t_ns) * 1e-9;
        if (t_s < t0_s || t_s > t1_s) continue;
        ++n;
        double enu[3];
        geodesy::geodetic_to_enu(origin, g.lat_deg, g.lon_deg, g.height_m, enu);
        const sim::TruthSample& t = out.truth[truth_index(out, g.header.t_ns)];
        s += std::hypot(enu[0] - t.pos_enu_m[0], enu[1] - t.pos_enu_m[1]);
    }
    return n ? s / n : NAN;
}

sim::Route block_laps_route() {
    nlohmann::json waypoints = nlohmann::json::array({{0, 0, 0}});
    for (int lap = 0; lap < 2; ++lap)
        for (const auto& p : {std::array<double, 2>{100, 0}, {100, 60}, {0, 60}, {0, 0}})
            waypoints.push_back({{"enu_m", {p[0], p[1], 0.0}}, {"outdoor", true}});
    return sim::parse_route({{"format", "pednav-route/1"},
                             {"name", "block_laps"},
                             {"start_still_s", 10},
                             {"end_still_s", 5},
                             {"waypoints", waypoints}});
}

void remove_fixes(sim::SimOutput& out, double t0_s, double t1_s) {
    std::vector<pn_gnss_t> kept;
    for (const pn_gnss_t& g : out.gnss) {
        const double t = static_cast<double>(g.header.t_ns) * 1e-9;
        if (t < t0_s || t > t1_s) kept.push_back(g);
    }
    out.gnss = kept;
}

std::string waist_preset(const std::string& source_dir) {
    const std::string path = source_dir + "/configs/waist.json";
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot open " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

}  // namespace pednav::waist_eval
