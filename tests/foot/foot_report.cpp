// Prints the foot pipeline's accuracy on every shared foot recording, for
// docs/foot-pipeline.md. Usage: foot_report [shoe|multicondition] [json merge patch] [mode]
// with mode full (the default: simulated walks at 400 Hz, then the recordings),
// sweep (the corridor loop over gaits, mountings and rates),
// quick (the real recordings only), sim (the simulated walks only, at 100, 200
// and 400 Hz), tables, hupt or clip.
#include <algorithm>
#include <cstdio>
#include <string>

#include "foot_eval.hpp"

using namespace pednav::foot_eval;

namespace {
// The simulated corridor loop and stairs, exact sensor and scaled MEMS errors.
void print_sim(const std::string& cfg, double rate_hz) {
    for (const char* route : {"corridor_loop", "stairs"}) {
        for (double errors : {0.0, 1.0, 5.0, -100.0, -300.0}) {
            SimCase c;
            c.route = route;
            c.sensor_errors = errors != 0;
            c.error_scale = errors > 0 ? errors : 1.0;
            c.accel_bias_walk_scale = errors < 0 ? -errors : 1.0;
            c.rate_hz = rate_hz;
            c.mounting_rpy_deg[0] = 20;
            c.mounting_rpy_deg[1] = -30;
            c.mounting_rpy_deg[2] = 10;
            const SimScore s = score_sim(c, cfg);
            std::printf("sim %-13s errors x%.0f strides %3zu/%3zu (level %zu stairs %zu) closure %.3f m %.3f %% max_h %.3f  z mean %.3f final %.3f\n",
                        route, errors, s.strides, s.true_strides, s.level, s.stairs, s.closure_m, s.closure_pct,
                        s.max_err_h_m, s.mean_err_z_m, s.final_err_z_m);
        }
    }
}

// Gaits, sensor mountings and rates the pipeline was not tuned on: the
// corridor loop at every combination, three seeds each, default MEMS errors
// (without the gyro scale-factor errors when `gyro_scale` is false: only
// the summary line).
void print_sweep(const std::string& cfg, bool gyro_scale) {
    static const double mounts[][3] = {{0, 0, 0}, {20, -30, 10}, {180, 0, 0}, {90, 0, 0}, {0, -80, 0}, {-150, 40, 120}};
    std::vector<double> all;
    for (const Gait& g : sweep_gaits()) {
        for (double rate : {100.0, 200.0, 256.0, 400.0}) {
            std::vector<double> pct;
            size_t wrong_strides = 0;
            for (const auto& m : mounts) {
                for (uint64_t seed = 1; seed <= 3; ++seed) {
                    SimCase c;
                    c.route = "corridor_loop";
                    c.rate_hz = rate;
                    c.seed = seed;
                    for (int i = 0; i < 3; ++i) c.mounting_rpy_deg[i] = m[i];
                    c.gait = g;
                    c.gyro_scale_errors = gyro_scale;
                    const SimScore s = score_sim(c, cfg);
                    pct.push_back(s.closure_pct);
                    all.push_back(s.closure_pct);
                    if (s.strides != s.true_strides) ++wrong_strides;
                    if (gyro_scale && (s.strides != s.true_strides || s.closure_pct > 0.5))
                        std::printf("  %s %.0f Hz mount %.0f/%.0f/%.0f seed %llu: strides %zu/%zu closure %.3f %%\n", g.name,
                                    rate, m[0], m[1], m[2], static_cast<unsigned long long>(seed), s.strides,
                                    s.true_strides, s.closure_pct);
                }
            }
            const Stats st = stats_of(pct);
            std::sort(pct.begin(), pct.end());
            if (gyro_scale)
                std::printf("sweep %-6s %3.0f Hz  runs %2zu  stride count wrong %zu  closure %% min %.3f median %.3f max %.3f\n",
                            g.name, rate, pct.size(), wrong_strides, st.min, pct[pct.size() / 2], st.max);
        }
    }
    std::sort(all.begin(), all.end());
    std::printf("sweep all%s  runs %zu  closure %% median %.3f  90th %.3f  max %.3f\n",
                gyro_scale ? "" : " (gyro scale-factor errors off)", all.size(), all[all.size() / 2],
                all[all.size() * 9 / 10], all.back());
}
}  // namespace

int main(int argc, char** argv) {
    const std::string det = argc > 1 ? argv[1] : "shoe";
    const std::string mode = argc > 3 ? argv[3] : "full";
    if (mode != "full" && mode != "quick" && mode != "sim" && mode != "tables" && mode != "hupt" && mode != "clip" &&
        mode != "sweep") {
        std::fprintf(stderr, "error: unknown mode '%s' (full, quick, sim, sweep, tables, hupt or clip)\n", mode.c_str());
        return 2;
    }
    try {
        nlohmann::json patch = detector_patch(det);
        if (argc > 2) patch.merge_patch(nlohmann::json::parse(argv[2]));
        const std::string cfg = foot_config(patch);
        if (mode == "tables") {
            // The paper's tables: |dx|, |dy| at the footprints, ZUPT only vs ZUPT + ZARU.
            for (bool zaru : {false, true}) {
                nlohmann::json p2 = patch;
                p2.merge_patch(ekf_patch({{"zaru", zaru}}));
                const std::string c2 = koroglu_config(p2);
                std::printf("%s\n", zaru ? "ZUPT + ZARU" : "ZUPT only");
                for (int n : {33, 35, 39, 42, 44}) {
                    const KorogluScore s = score_koroglu(n, c2);
                    std::vector<double> ax, ay;
                    for (double v : s.dx) ax.push_back(std::abs(v) * 100);
                    for (double v : s.dy) ay.push_back(std::abs(v) * 100);
                    const Stats x = stats_of(ax), y = stats_of(ay);
                    std::printf("  %d dx cm min %.0f max %.0f mean %.0f sd %.0f | dy cm min %.0f max %.0f mean %.0f sd %.0f | mean err %.2f %%\n",
                                n, x.min, x.max, x.mean, x.sd, y.min, y.max, y.mean, y.sd, s.mean_pct);
                }
            }
            return 0;
        }
        if (mode == "clip") {
            // The xio loops with the gyro clipped as a +-500/450/400 deg/s sensor
            // would read it, against the unclipped loops.
            for (double dps : {500.0, 450.0, 400.0}) {
                for (const char* w : {"short_walk", "long_walk"}) {
                    for (bool range : {false, true}) {
                        const ClipScore c = score_xio_clipped(w, cfg, dps * M_PI / 180.0, range);
                        std::printf("clip %3.0f deg/s %-10s range %-5s clipped samples %4zu strides %zu/%zu  footprints "
                                    "%.3f m rms  heading %.2f deg rms\n",
                                    dps, w, range ? "given" : "no", c.clipped_samples, c.strides, c.strides_unclipped,
                                    c.footprint_rms_m, c.heading_rms_deg);
                    }
                }
            }
            return 0;
        }
        if (mode == "hupt") {
            // Mean |height error| at the stance samples, ZUPT only vs the
            // preset (HUPT with the level memory), 200 Hz, four seeds.
            nlohmann::json p0 = patch;
            p0.merge_patch(ekf_patch({{"hupt", false}}));
            const std::string zupt_cfg = foot_config(p0);
            for (const char* route : {"stairs", "building_tour"}) {
                for (double errors : {1.0, 5.0}) {
                    for (uint64_t seed = 1; seed <= 4; ++seed) {
                        SimCase c;
                        c.route = route;
                        c.error_scale = errors;
                        c.seed = seed;
                        c.mounting_rpy_deg[0] = 20;
                        c.mounting_rpy_deg[1] = -30;
                        c.mounting_rpy_deg[2] = 10;
                        const SimScore z = score_sim(c, zupt_cfg);
                        const SimScore h = score_sim(c, cfg);
                        std::printf("hupt %-13s errors x%.0f seed %llu  mean |dz| ZUPT %.3f m  HUPT %.3f m  cut %3.0f %%  "
                                    "final ZUPT %.3f m  HUPT %.3f m\n",
                                    route, errors, static_cast<unsigned long long>(seed), z.mean_err_z_m, h.mean_err_z_m,
                                    100.0 * (1.0 - h.mean_err_z_m / z.mean_err_z_m), z.final_err_z_m, h.final_err_z_m);
                    }
                }
            }
            return 0;
        }
        std::printf("detector %s\n", det.c_str());
        if (mode == "sim") {
            for (double rate : {100.0, 200.0, 400.0}) {
                std::printf("rate %.0f Hz\n", rate);
                print_sim(cfg, rate);
            }
            return 0;
        }
        if (mode == "sweep") {
            print_sweep(cfg, true);
            print_sweep(cfg, false);
            return 0;
        }
        if (mode == "full") print_sim(cfg, 400);
        for (const char* w : {"short_walk", "long_walk"}) {
            const XioScore s = score_xio(w, cfg);
            std::printf("xio %-11s strides %3zu  walked %6.2f m  closure %.3f m (h %.3f)  %.2f %%\n", w, s.strides,
                        s.distance_m, s.closure_m, s.closure_h_m, s.closure_pct);
        }
        const std::string koroglu_cfg = koroglu_config(patch);
        for (int n : {33, 35, 39, 42, 44}) {
            const KorogluScore s = score_koroglu(n, koroglu_cfg);
            std::printf("koroglu %d strides %3zu/%3zu  path %6.1f m (estimated %+.1f %%)  mean %.3f max %.3f final %.3f m  mean %.2f %%\n",
                        n, s.strides, s.footprints, s.path_m, 100.0 * (s.est_path_m / s.path_m - 1.0), s.err_m.mean,
                        s.err_m.max, s.err_m.final, s.mean_pct);
        }
        if (mode == "full") {
            for (const char* t : {"1-1", "1-2", "5-1", "5-2", "10-1", "10-2", "15-1", "19-1"}) {
                for (const char* f : {"lf", "rf"}) {
                    const IpolScore s = score_ipol(t, f, cfg);
                    std::printf("ipol %-4s %s strides %2zu/%2zu  out %6.2f m  back %6.2f m  (annotated: out %6.2f m  back "
                                "%6.2f m)\n",
                                t, f, s.strides, s.footsteps, s.leg_out_m, s.leg_back_m, s.annotated_out_m,
                                s.annotated_back_m);
                }
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
