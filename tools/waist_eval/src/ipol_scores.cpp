// SPDX-License-Identifier: Apache-2.0
#include <pednav_waist_eval/ipol_scores.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_eval/walks.hpp>
#include <pednav_foot_eval/runs.hpp>
#include <pednav_foot_eval/scores.hpp>
#include <pednav_navmath/angles.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_pdr/inverted_pendulum.hpp>
#include <pednav_pdr/step_length_model.hpp>
#include <pednav_pdr/vertical_acceleration.hpp>

namespace pednav::waist_eval {

namespace {
double hypot2(const double* a, const double* b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }
double t_of(int64_t t_ns) { return static_cast<double>(t_ns) * 1e-9; }

// The step detector's gravity_time_constant_s in a config.
double gravity_time_constant_s(const std::string& config_json) {
    const nlohmann::json doc = nlohmann::json::parse(config_json);
    for (const auto& [name, pipeline] : doc.at("pipelines").items()) {
        (void)name;
        const auto it = pipeline.find("step_detector");
        if (it != pipeline.end() && it->contains("params") && it->at("params").contains("gravity_time_constant_s"))
            return it->at("params").at("gravity_time_constant_s").get<double>();
    }
    throw std::runtime_error("the waist config has no step_detector gravity_time_constant_s");
}

// The track's horizontal position at t: linear between the outputs around
// it (the start point before the first, the last output after it).
void position_at(const ReplayResult& r, double t_s, double out[2]) {
    double t_prev = 0, prev[2] = {0, 0};
    for (const pn_position_t& p : r.positions) {
        const double t = t_of(p.header.t_ns);
        if (t >= t_s) {
            const double u = t > t_prev ? (t_s - t_prev) / (t - t_prev) : 1.0;
            for (int i = 0; i < 2; ++i) out[i] = prev[i] + std::clamp(u, 0.0, 1.0) * (p.pos_enu_m[i] - prev[i]);
            return;
        }
        t_prev = t;
        prev[0] = p.pos_enu_m[0];
        prev[1] = p.pos_enu_m[1];
    }
    out[0] = prev[0];
    out[1] = prev[1];
}
}  // namespace

const std::vector<std::string>& ipol_waist_trials() {
    static const std::vector<std::string> trials = {"1-1", "1-2", "2-1", "2-2", "3-1", "3-2", "4-1",
                                                    "4-2", "5-1", "5-2", "6-1", "6-2", "7-1", "7-2",
                                                    "8-1", "8-2", "10-1", "10-2", "15-1", "19-1"};
    return trials;
}

std::string ipol_subject(const std::string& trial) { return trial.substr(0, trial.find('-')); }

IpolWaistRun run_ipol_waist(const std::string& data_dir, const std::string& trial, const std::string& config_json,
                            const std::vector<std::string>& plugin_dirs) {
    const eval::RecordedWalk walk = eval::ipol_walk(data_dir, trial, "lb");
    const eval::Truth truth = eval::read_ipol_steps(walk.truth_path, eval::kIpolRateHz, eval::kIpolLegM, "both");
    if (truth.legs.size() != 2 || truth.step_times_s.empty())
        throw std::runtime_error(walk.truth_path + ": expected footsteps and an out and a back leg");
    const io::SensorLog log = io::read_sensor_file(walk.input);
    const ReplayResult r = foot_eval::run_log(log, config_json, plugin_dirs, walk.input);
    if (r.positions.empty()) throw std::runtime_error(walk.input + ": no positions");
    IpolWaistRun run;
    run.trial = trial;
    run.height_m = eval::read_ipol_height_m(walk.truth_path);
    // The vertical acceleration the step detector sees, for the pelvis' rise.
    std::vector<int64_t> t_v;
    std::vector<double> a_v;
    pdr::VerticalAcceleration vertical(gravity_time_constant_s(config_json));
    for (const pn_imu_t& s : log.imu) {
        t_v.push_back(s.header.t_ns);
        a_v.push_back(vertical.push(s.header.t_ns, s.accel_mps2));
    }
    const auto pelvis_rise = [&](int64_t t0_ns, int64_t t1_ns) {
        const size_t i0 = static_cast<size_t>(std::lower_bound(t_v.begin(), t_v.end(), t0_ns) - t_v.begin());
        const size_t i1 = static_cast<size_t>(std::upper_bound(t_v.begin(), t_v.end(), t1_ns) - t_v.begin());
        return i1 > i0 ? pdr::pelvis_rise_m(t_v.data() + i0, a_v.data() + i0, i1 - i0) : 0.0;
    };
    run.footsteps = truth.step_count;
    const double t0 = truth.step_times_s.front() - 0.3, t1 = truth.step_times_s.back() + 0.3;
    for (const pn_step_t& s : r.steps)
        if (s.motion_mode != PN_STEP_MODE_STATIC && t_of(s.header.t_ns) >= t0 && t_of(s.header.t_ns) <= t1)
            ++run.steps;

    // The dataset's own legs (walk start to U-turn start, U-turn end to walk
    // end): the chord between the track's positions at those times, which
    // are linear between the per-step outputs.
    for (int leg = 0; leg < 2; ++leg) {
        const eval::Leg& l = truth.legs[leg];
        double a[2], b[2];
        position_at(r, l.t0_s, a);
        position_at(r, l.t1_s, b);
        const double chord = hypot2(a, b);
        double path = 0;
        std::vector<double>& ranges = leg == 0 ? run.out_ranges_mps2 : run.back_ranges_mps2;
        for (const pn_stride_t& s : r.strides)
            if (t_of(s.header.t_ns) > l.t0_s && t_of(s.header.t_ns) <= l.t1_s) path += s.length_m;
        std::vector<IpolStep>& steps = leg == 0 ? run.out_steps : run.back_steps;
        for (const pn_step_t& s : r.steps)
            if (s.motion_mode != PN_STEP_MODE_STATIC && t_of(s.header.t_ns) > l.t0_s && t_of(s.header.t_ns) <= l.t1_s) {
                ranges.push_back(s.accel_peak_to_peak_mps2);
                steps.push_back({s.accel_peak_to_peak_mps2, s.frequency_hz, pelvis_rise(s.t_start_ns, s.header.t_ns)});
            }
        (leg == 0 ? run.leg_out_m : run.leg_back_m) = chord;
        (leg == 0 ? run.out_path_ratio : run.back_path_ratio) = chord > 0 ? path / chord : 1.0;
    }

    // Headings of the annotated legs (circular means of the track's heading).
    const auto mean_heading = [&](const eval::Leg& leg) {
        double s = 0, c = 0;
        for (const pn_position_t& p : r.positions)
            if (t_of(p.header.t_ns) >= leg.t0_s && t_of(p.header.t_ns) <= leg.t1_s)
                s += std::sin(p.heading_rad), c += std::cos(p.heading_rad);
        return std::atan2(s, c);
    };
    run.uturn_deg =
        std::abs(navmath::wrap_pi(mean_heading(truth.legs[1]) - mean_heading(truth.legs[0]))) * 180.0 / M_PI;
    return run;
}

FootLegs ipol_foot_legs(const std::string& data_dir, const std::string& trial, const std::string& foot_config_json,
                        const std::vector<std::string>& plugin_dirs) {
    const foot_eval::IpolScore lf = foot_eval::score_ipol(eval::ipol_walk(data_dir, trial, "lf"), foot_config_json,
                                                          plugin_dirs);
    const foot_eval::IpolScore rf = foot_eval::score_ipol(eval::ipol_walk(data_dir, trial, "rf"), foot_config_json,
                                                          plugin_dirs);
    return {0.5 * (lf.annotated_out_m + rf.annotated_out_m), 0.5 * (lf.annotated_back_m + rf.annotated_back_m)};
}

std::string with_step_model(const std::string& config_json, double k, double b, double beta_m) {
    nlohmann::json doc = nlohmann::json::parse(config_json);
    for (auto& [name, pipeline] : doc.at("pipelines").items()) {
        (void)name;
        auto& params = pipeline.at("position_filter")["params"];
        params["step_model_k"] = k;
        params["step_model_b"] = b;
        params["step_model_beta_m"] = beta_m;
    }
    return doc.dump();
}

std::vector<IpolTrial> ipol_trials(const std::string& data_dir, const std::string& waist_config_json,
                                   const std::string& foot_config_json, const std::vector<std::string>& plugin_dirs) {
    std::vector<IpolTrial> trials;
    for (const std::string& t : ipol_waist_trials())
        trials.push_back({t, ipol_subject(t), run_ipol_waist(data_dir, t, waist_config_json, plugin_dirs),
                          ipol_foot_legs(data_dir, t, foot_config_json, plugin_dirs)});
    return trials;
}

std::vector<LosoLeg> leave_one_subject_out(const std::string& data_dir, const std::string& waist_config_json,
                                           const std::string& foot_config_json,
                                           const std::vector<std::string>& plugin_dirs, double b) {
    return leave_one_subject_out(ipol_trials(data_dir, waist_config_json, foot_config_json, plugin_dirs), data_dir,
                                 waist_config_json, plugin_dirs, b);
}

std::vector<LosoLeg> leave_one_subject_out(const std::vector<IpolTrial>& trials, const std::string& data_dir,
                                           const std::string& waist_config_json,
                                           const std::vector<std::string>& plugin_dirs, double b) {
    std::map<std::string, double> k_of;
    for (const IpolTrial& held : trials) {
        if (k_of.count(held.subject)) continue;
        std::vector<pdr::CalibrationWalk> walks;
        for (const IpolTrial& t : trials) {
            if (t.subject == held.subject) continue;
            // The steps of a leg cover the waist's path over it, a little
            // longer than its chord (the pelvis' yaw swing): the foot's chord
            // times the waist's path-to-chord ratio.
            walks.push_back({t.run.out_ranges_mps2, t.foot.out_m * t.run.out_path_ratio});
            walks.push_back({t.run.back_ranges_mps2, t.foot.back_m * t.run.back_path_ratio});
        }
        k_of[held.subject] = pdr::fit_step_length(walks, b, false, 0.0).model.k;
    }
    std::vector<LosoLeg> legs;
    for (const IpolTrial& t : trials) {
        const double k = k_of.at(t.subject);
        const IpolWaistRun run = run_ipol_waist(data_dir, t.trial, with_step_model(waist_config_json, k, b, 0.0),
                                                plugin_dirs);
        legs.push_back({t.trial, t.subject, true, run.leg_out_m, t.foot.out_m, k});
        legs.push_back({t.trial, t.subject, false, run.leg_back_m, t.foot.back_m, k});
    }
    return legs;
}

}  // namespace pednav::waist_eval
