// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_engine/replay.hpp>
#include <pednav_foot_eval/scores.hpp>
#include <pednav_sim/simulate.hpp>

namespace pednav::foot_eval {

SimScore score_sim(const eval::SimulatedWalk& walk, const std::string& config_json,
                   const std::vector<std::string>& plugin_dirs) {
    const sim::SimOutput out = sim::simulate(eval::sim_route(walk), eval::sim_options(walk));
    auto doc = nlohmann::json::parse(config_json);
    doc["imu_rate_hz"] = walk.rate_hz;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = plugin_dirs;
    // The truth's start point (not its heading: the attitude estimator does not know the walking direction).
    const auto& t0 = out.truth.front();
    for (int i = 0; i < 3; ++i) o.start_enu_m[i] = t0.pos_enu_m[i];
    const ReplayResult r = replay(o, out.records());
    if (!r.error.empty()) throw std::runtime_error("sim " + walk.route + ": " + r.error);
    if (r.positions.empty()) throw std::runtime_error("sim " + walk.route + ": no positions");
    SimScore sc;
    sc.distance_m = out.distance_m;
    sc.strides = r.strides.size();
    sc.true_strides = out.step_times_s.size();
    for (const auto& s : r.strides) (s.stride_class == PN_STRIDE_CLASS_LEVEL ? sc.level : sc.stairs)++;
    const auto& a = r.positions.front();
    const auto& b = r.positions.back();
    sc.closure_m = std::hypot(a.pos_enu_m[0] - b.pos_enu_m[0], a.pos_enu_m[1] - b.pos_enu_m[1]);
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
    std::vector<std::array<double, 2>> est, truth;
    j = k;
    for (const auto& p : r.positions) {
        while (j + 1 < out.truth.size() && out.truth[j].t_s * 1e9 < p.header.t_ns - 1000) ++j;
        est.push_back({p.pos_enu_m[0] - a.pos_enu_m[0], p.pos_enu_m[1] - a.pos_enu_m[1]});
        truth.push_back({out.truth[j].pos_enu_m[0] - ta.pos_enu_m[0], out.truth[j].pos_enu_m[1] - ta.pos_enu_m[1]});
    }
    const double ang = eval::procrustes_rotation_rad(est, truth), cs = std::cos(ang), sn = std::sin(ang);
    for (size_t i = 0; i < est.size(); ++i)
        sc.max_err_h_m = std::max(sc.max_err_h_m, std::hypot(cs * est[i][0] - sn * est[i][1] - truth[i][0],
                                                             sn * est[i][0] + cs * est[i][1] - truth[i][1]));
    return sc;
}

}  // namespace pednav::foot_eval
