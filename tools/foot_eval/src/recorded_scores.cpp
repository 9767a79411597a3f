// SPDX-License-Identifier: Apache-2.0
#include <array>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_foot_eval/runs.hpp>
#include <pednav_foot_eval/scores.hpp>
#include <pednav_io/sensor_log.hpp>

namespace pednav::foot_eval {

namespace {
double hypot2(const double* a, const double* b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }
}  // namespace

XioScore score_xio(const eval::RecordedWalk& walk, const std::string& config_json,
                   const std::vector<std::string>& plugin_dirs) {
    XioScore sc;
    sc.name = walk.name;
    const ReplayResult r = run_recording(walk.input, config_json, plugin_dirs);
    if (r.positions.empty()) throw std::runtime_error(walk.name + ": no positions");
    const auto& a = r.positions.front();
    const auto& b = r.positions.back();
    sc.closure_h_m = hypot2(a.pos_enu_m, b.pos_enu_m);
    sc.closure_m = std::hypot(sc.closure_h_m, b.pos_enu_m[2] - a.pos_enu_m[2]);
    sc.distance_m = stride_path_m(r);
    sc.closure_pct = sc.distance_m > 0 ? 100.0 * sc.closure_m / sc.distance_m : 100.0;
    sc.strides = r.strides.size();
    return sc;
}

ClipScore score_xio_clipped(const eval::RecordedWalk& walk, const std::string& config_json,
                            const std::vector<std::string>& plugin_dirs, double clip_radps, bool tell_range) {
    ClipScore sc;
    io::SensorLog log = io::read_sensor_file(walk.input);
    const ReplayResult ref = run_log(log, config_json, plugin_dirs, walk.name);
    for (auto& r : log.imu)
        for (double& g : r.gyro_radps)
            if (std::abs(g) > clip_radps) {
                g = std::copysign(clip_radps, g);
                ++sc.clipped_samples;
            }
    auto doc = nlohmann::json::parse(config_json);
    if (tell_range) doc["pipelines"]["foot"]["attitude_estimator"]["params"]["gyro_range_radps"] = clip_radps;
    const ReplayResult r = run_log(log, doc.dump(), plugin_dirs, walk.name + " clipped");
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

KorogluScore score_koroglu(const eval::RecordedWalk& walk, const std::string& config_json,
                           const std::vector<std::string>& plugin_dirs) {
    KorogluScore sc;
    sc.name = walk.name;
    // One footprint per stride at the end of its stance; stride 0 is the start.
    const eval::Truth truth = eval::read_walk_truth(walk);
    if (truth.kind != eval::TruthKind::footprints) throw std::runtime_error(walk.name + ": not a footprint truth");
    const std::vector<eval::TruthPoint>& gcp = truth.points;
    sc.footprints = gcp.size() - 1;
    sc.path_m = truth.distance_m;

    const ReplayResult r = run_recording(walk.input, config_json, plugin_dirs);
    sc.strides = r.strides.size();
    // Estimated footprint: the position at the end of each annotated stance,
    // relative to the one of stride 0.
    std::vector<std::array<double, 2>> est;
    for (const eval::TruthPoint& g : gcp) {
        const auto& p = position_at(r, g.t_s);
        est.push_back({p.pos_enu_m[0], p.pos_enu_m[1]});
    }
    for (size_t i = 1; i < est.size(); ++i)
        sc.est_path_m += std::hypot(est[i][0] - est[i - 1][0], est[i][1] - est[i - 1][1]);
    const std::array<double, 2> start = est[0];
    for (auto& e : est) e = {e[0] - start[0], e[1] - start[1]};
    // One rotation fitted on the first 5 strides (footprints 1..5), least squares.
    const size_t fit = std::min<size_t>(5, est.size() - 1);
    std::vector<std::array<double, 2>> fit_est(est.begin() + 1, est.begin() + 1 + fit), fit_gcp;
    for (size_t i = 1; i <= fit; ++i) fit_gcp.push_back({gcp[i].x_m, gcp[i].y_m});
    const double ang = eval::procrustes_rotation_rad(fit_est, fit_gcp), c = std::cos(ang), s = std::sin(ang);
    std::vector<double> err;
    for (size_t i = 0; i < est.size(); ++i) {
        const double x = c * est[i][0] - s * est[i][1], y = s * est[i][0] + c * est[i][1];
        sc.dx.push_back(x - gcp[i].x_m);
        sc.dy.push_back(y - gcp[i].y_m);
        err.push_back(std::hypot(x - gcp[i].x_m, y - gcp[i].y_m));
    }
    sc.err_m = eval::error_stats(err);
    sc.final_error_m = err.back();
    sc.mean_pct = 100.0 * sc.err_m.mean / sc.path_m;
    return sc;
}

IpolScore score_ipol(const eval::RecordedWalk& walk, const std::string& config_json,
                     const std::vector<std::string>& plugin_dirs) {
    IpolScore sc;
    sc.name = walk.name;
    const eval::Truth truth =
        eval::read_ipol_steps(walk.truth_path, eval::kIpolRateHz, eval::kIpolLegM, walk.feet, true);
    if (truth.legs.size() != 2) throw std::runtime_error(walk.name + ": expected an out and a back leg");
    const ReplayResult r = run_recording(walk.input, config_json, plugin_dirs);
    if (r.positions.empty()) throw std::runtime_error(walk.name + ": no positions");
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
    sc.footsteps = static_cast<size_t>(truth.step_count);
    // The dataset's own legs: out from the walk's start to the U-turn's, back
    // from the U-turn's end to the walk's end.
    const auto leg = [&](const eval::Leg& l) {
        return hypot2(position_at(r, l.t0_s).pos_enu_m, position_at(r, l.t1_s).pos_enu_m);
    };
    sc.annotated_out_m = leg(truth.legs[0]);
    sc.annotated_back_m = leg(truth.legs[1]);
    return sc;
}

}  // namespace pednav::foot_eval
