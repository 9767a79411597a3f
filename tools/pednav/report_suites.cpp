// SPDX-License-Identifier: Apache-2.0
#include "report_suites.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_eval/walks.hpp>
#include <pednav_foot_eval/patches.hpp>
#include <pednav_foot_eval/scores.hpp>

namespace pednav::cli {

namespace {

using namespace pednav::foot_eval;

// The config of one recorded walk: the preset with the patch, and the
// sensor's gyro range where the walk's sensor clips.
std::string walk_config(const FootSuiteSetup& s, const nlohmann::json& patch, const eval::RecordedWalk& walk) {
    return eval::patched_config(s.preset_json, with_gyro_range(patch, walk.gyro_range_radps));
}

// The simulated corridor loop and stairs, exact sensor and scaled MEMS errors.
void print_imu_error_walks(const FootSuiteSetup& s, const std::string& cfg, double rate_hz) {
    for (const eval::SimulatedWalk& w : eval::imu_error_walks(rate_hz)) {
        // x0: exact sensor; xN: every error times N; x-N: the accelerometer bias walk times N.
        const double errors =
            !w.sensor_errors ? 0.0 : (w.accel_bias_walk_scale != 1.0 ? -w.accel_bias_walk_scale : w.error_scale);
        const SimScore r = score_sim(w, cfg, s.plugin_dirs);
        std::printf("sim %-13s errors x%.0f strides %3zu/%3zu (level %zu stairs %zu) closure %.3f m %.3f %% max_h %.3f  z mean %.3f final %.3f\n",
                    w.route.c_str(), errors, r.strides, r.true_strides, r.level, r.stairs, r.closure_m, r.closure_pct,
                    r.max_err_h_m, r.mean_err_z_m, r.final_err_z_m);
    }
}

// Gaits, sensor mountings and rates the pipeline was not tuned on: the
// corridor loop at every combination, three seeds each, default MEMS errors
// (without the gyro scale-factor errors when `gyro_scale` is false: only the
// summary line). Median and 90th percentile: the upper order statistic.
void print_sweep(const FootSuiteSetup& s, const std::string& cfg, bool gyro_scale) {
    const std::vector<eval::SimulatedWalk> walks = eval::sweep_walks(gyro_scale);
    std::vector<double> all, cell;
    size_t wrong_strides = 0;
    for (size_t i = 0; i < walks.size(); ++i) {
        const eval::SimulatedWalk& w = walks[i];
        const SimScore r = score_sim(w, cfg, s.plugin_dirs);
        cell.push_back(r.closure_pct);
        all.push_back(r.closure_pct);
        if (r.strides != r.true_strides) ++wrong_strides;
        if (gyro_scale && (r.strides != r.true_strides || r.closure_pct > 0.5))
            std::printf("  %s %.0f Hz mount %.0f/%.0f/%.0f seed %llu: strides %zu/%zu closure %.3f %%\n", w.gait.name,
                        w.rate_hz, w.mounting_rpy_deg[0], w.mounting_rpy_deg[1], w.mounting_rpy_deg[2],
                        static_cast<unsigned long long>(w.seed), r.strides, r.true_strides, r.closure_pct);
        const bool cell_done = i + 1 == walks.size() || walks[i + 1].gait.name != w.gait.name ||
                               walks[i + 1].rate_hz != w.rate_hz;
        if (!cell_done) continue;
        if (gyro_scale)
            std::printf("sweep %-6s %3.0f Hz  runs %2zu  stride count wrong %zu  closure %% min %.3f median %.3f max %.3f\n",
                        w.gait.name, w.rate_hz, cell.size(), wrong_strides, eval::percentile(cell, 0),
                        eval::percentile(cell, 50, eval::PercentileMethod::higher), eval::percentile(cell, 100));
        cell.clear();
        wrong_strides = 0;
    }
    std::printf("sweep all%s  runs %zu  closure %% median %.3f  90th %.3f  max %.3f\n",
                gyro_scale ? "" : " (gyro scale-factor errors off)", all.size(),
                eval::percentile(all, 50, eval::PercentileMethod::higher),
                eval::percentile(all, 90, eval::PercentileMethod::higher), eval::percentile(all, 100));
}

// The paper's tables: |dx|, |dy| at the footprints (cm, sample SD), ZUPT only vs ZUPT + ZARU.
void print_tables(const FootSuiteSetup& s) {
    for (bool zaru : {false, true}) {
        nlohmann::json patch = s.patch;
        patch.merge_patch(ekf_patch({{"zaru", zaru}}));
        std::printf("%s\n", zaru ? "ZUPT + ZARU" : "ZUPT only");
        for (int n : eval::koroglu_walk_numbers()) {
            const eval::RecordedWalk walk = eval::koroglu_walk(s.data_dir, n);
            const KorogluScore r = score_koroglu(walk, walk_config(s, patch, walk), s.plugin_dirs);
            std::vector<double> ax, ay;
            for (double v : r.dx) ax.push_back(std::abs(v) * 100);
            for (double v : r.dy) ay.push_back(std::abs(v) * 100);
            const eval::AxisStats x = eval::axis_stats(ax, 1), y = eval::axis_stats(ay, 1);
            std::printf("  %d dx cm min %.0f max %.0f mean %.0f sd %.0f | dy cm min %.0f max %.0f mean %.0f sd %.0f | mean err %.2f %%\n",
                        n, x.min, x.max, x.mean, x.sd, y.min, y.max, y.mean, y.sd, r.mean_pct);
        }
    }
}

// The xio loops with the gyro clipped as a +-500/450/400 deg/s sensor would
// read it, against the unclipped loops.
void print_clip(const FootSuiteSetup& s, const std::string& cfg) {
    for (double dps : {500.0, 450.0, 400.0}) {
        for (const std::string& name : eval::xio_walk_names()) {
            for (bool range : {false, true}) {
                const ClipScore c =
                    score_xio_clipped(eval::xio_walk(s.data_dir, name), cfg, s.plugin_dirs, dps * M_PI / 180.0, range);
                std::printf("clip %3.0f deg/s %-10s range %-5s clipped samples %4zu strides %zu/%zu  footprints "
                            "%.3f m rms  heading %.2f deg rms\n",
                            dps, name.c_str(), range ? "given" : "no", c.clipped_samples, c.strides,
                            c.strides_unclipped, c.footprint_rms_m, c.heading_rms_deg);
            }
        }
    }
}

// Mean |height error| at the stance samples, ZUPT only vs the preset (HUPT
// with the level memory), 200 Hz, four seeds.
void print_hupt(const FootSuiteSetup& s, const std::string& cfg) {
    nlohmann::json zupt_patch = s.patch;
    zupt_patch.merge_patch(ekf_patch({{"hupt", false}}));
    const std::string zupt_cfg = eval::patched_config(s.preset_json, zupt_patch);
    for (const eval::SimulatedWalk& w : eval::hupt_walks()) {
        const SimScore z = score_sim(w, zupt_cfg, s.plugin_dirs);
        const SimScore h = score_sim(w, cfg, s.plugin_dirs);
        std::printf("hupt %-13s errors x%.0f seed %llu  mean |dz| ZUPT %.3f m  HUPT %.3f m  cut %3.0f %%  "
                    "final ZUPT %.3f m  HUPT %.3f m\n",
                    w.route.c_str(), w.error_scale, static_cast<unsigned long long>(w.seed), z.mean_err_z_m,
                    h.mean_err_z_m, 100.0 * (1.0 - h.mean_err_z_m / z.mean_err_z_m), z.final_err_z_m,
                    h.final_err_z_m);
    }
}

// The recordings: xio loops and koroglu footprints; with `ipol`, the ipol foot files too.
void print_recordings(const FootSuiteSetup& s, const std::string& cfg, bool ipol) {
    for (const std::string& name : eval::xio_walk_names()) {
        const XioScore r = score_xio(eval::xio_walk(s.data_dir, name), cfg, s.plugin_dirs);
        std::printf("xio %-11s strides %3zu  walked %6.2f m  closure %.3f m (h %.3f)  %.2f %%\n", name.c_str(),
                    r.strides, r.distance_m, r.closure_m, r.closure_h_m, r.closure_pct);
    }
    for (int n : eval::koroglu_walk_numbers()) {
        const eval::RecordedWalk walk = eval::koroglu_walk(s.data_dir, n);
        const KorogluScore r = score_koroglu(walk, walk_config(s, s.patch, walk), s.plugin_dirs);
        std::printf("koroglu %d strides %3zu/%3zu  path %6.1f m (estimated %+.1f %%)  mean %.3f max %.3f final %.3f m  mean %.2f %%\n",
                    n, r.strides, r.footprints, r.path_m, 100.0 * (r.est_path_m / r.path_m - 1.0), r.err_m.mean,
                    r.err_m.max, r.final_error_m, r.mean_pct);
    }
    if (!ipol) return;
    for (const std::string& trial : eval::ipol_trials()) {
        for (const std::string& part : eval::ipol_parts()) {
            const eval::RecordedWalk walk = eval::ipol_walk(s.data_dir, trial, part);
            if (walk.mount != "foot") continue;
            const IpolScore r = score_ipol(walk, cfg, s.plugin_dirs);
            std::printf("ipol %-4s %s strides %2zu/%2zu  out %6.2f m  back %6.2f m  (annotated: out %6.2f m  back "
                        "%6.2f m)\n",
                        trial.c_str(), part.c_str(), r.strides, r.footsteps, r.leg_out_m, r.leg_back_m,
                        r.annotated_out_m, r.annotated_back_m);
        }
    }
}

}  // namespace

const std::vector<std::string>& foot_suite_names() {
    static const std::vector<std::string> names = {"full", "quick", "sim", "sweep", "tables", "hupt", "clip"};
    return names;
}

bool foot_suite_reads_recordings(const std::string& suite) {
    return suite == "full" || suite == "quick" || suite == "tables" || suite == "clip";
}

void run_foot_suite(const std::string& suite, const FootSuiteSetup& s) {
    const auto& names = foot_suite_names();
    if (std::find(names.begin(), names.end(), suite) == names.end())
        throw std::runtime_error("unknown suite '" + suite + "'");
    const std::string cfg = eval::patched_config(s.preset_json, s.patch);
    if (suite == "tables") return print_tables(s);
    if (suite == "clip") return print_clip(s, cfg);
    if (suite == "hupt") return print_hupt(s, cfg);
    std::printf("detector %s\n", s.detector.c_str());
    if (suite == "sim") {
        for (double rate : {100.0, 200.0, 400.0}) {
            std::printf("rate %.0f Hz\n", rate);
            print_imu_error_walks(s, cfg, rate);
        }
    } else if (suite == "sweep") {
        print_sweep(s, cfg, true);
        print_sweep(s, cfg, false);
    } else if (suite == "full") {
        print_imu_error_walks(s, cfg, 400);
        print_recordings(s, cfg, true);
    } else {  // quick
        print_recordings(s, cfg, false);
    }
}

}  // namespace pednav::cli
