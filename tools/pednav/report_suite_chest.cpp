// SPDX-License-Identifier: Apache-2.0
#include "report_suite_chest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <pednav_chest_eval/calibrated_config.hpp>
#include <pednav_chest_eval/walk_scores.hpp>
#include <pednav_eval/config_patch.hpp>
#include <pednav_eval/metrics.hpp>
#include <pednav_eval/walks.hpp>

namespace pednav::cli {

namespace {

using chest_eval::WalkScore;

const std::vector<std::string> kSimRoutes = {"corridor_loop", "stairs", "building_tour", "figure_eight"};
constexpr int kSeeds = 3;

struct Preset {
    std::string label;  // as printed
    const char* mount;  // the pipeline's key in the config
    const std::string* json;
};

double median(std::vector<double> v) { return eval::percentile(std::move(v), 50); }
double worst(const std::vector<double>& v) { return v.empty() ? NAN : *std::max_element(v.begin(), v.end()); }

// The walks the suite calibrates the simulated pipelines on: a route and seed
// none of the scored walks has.
eval::SimulatedWalk calibration_sim(const std::string& mount) {
    eval::SimulatedWalk w = eval::builtin_sim_walks(mount, 9).front();  // corridor_loop, seed 9
    return w;
}

void print_humolire(const ChestSuiteSetup& s, const Preset& p) {
    const std::vector<std::string>& names = eval::humolire_walk_names();
    for (bool calibrated : {false, true}) {
        std::printf("humolire-phone, %s%s, no map: error at each landmark (m)\n", p.label.c_str(),
                    calibrated ? ", calibrated on the other walks' landmarks" : "");
        std::printf("  %-16s %9s %6s %6s %6s %6s %8s\n", "walk", "landmarks", "mean", "median", "p75", "max", "dist(m)");
        std::vector<double> p75s, means;
        for (const std::string& name : names) {
            std::string cfg = *p.json;
            std::string fit;
            if (calibrated) {
                std::vector<eval::RecordedWalk> others;
                for (const std::string& o : names)
                    if (o != name) others.push_back(eval::humolire_walk(s.data_dir, o));
                const chest_eval::Calibrated c = chest_eval::calibrate_on_recordings(cfg, p.mount, others, s.plugin_dirs);
                cfg = c.config_json;
                fit = c.summary.substr(0, c.summary.find(" ("));
            }
            const WalkScore w = chest_eval::score_recorded(eval::humolire_walk(s.data_dir, name), cfg, s.plugin_dirs);
            const eval::ErrorStats& e = w.metrics.horizontal_m;
            std::printf("  %-16s %9zu %6.2f %6.2f %6.2f %6.2f %8.1f  %s\n", name.c_str(), e.n, e.mean, e.median, e.p75,
                        e.max, w.distance_m, fit.c_str());
            p75s.push_back(e.p75);
            means.push_back(e.mean);
        }
        std::printf("  spread over %zu walks: mean error median %.2f worst %.2f; p75 median %.2f worst %.2f\n\n",
                    names.size(), median(means), worst(means), median(p75s), worst(p75s));
    }
}

void print_biba(const ChestSuiteSetup& s, const Preset& p) {
    std::printf("biba-chest-xsens, %s (no truth: steps, distance, magnetometer use, end point)\n", p.label.c_str());
    for (const char* name : {"kar_to_rita", "rita_to_kar", "K_calibration_test1-000"}) {
        const std::string path = s.data_dir + "/biba-chest-xsens/" + name + ".txt";
        const ReplayResult r = chest_eval::run_recording(path, *p.json, s.plugin_dirs);
        double d = 0;
        for (const pn_stride_t& st : r.strides) d += st.length_m;
        const pn_position_t& last = r.positions.back();
        std::printf("  %-24s steps %4zu  distance %6.1f m  mag used %5.1f %%  end (%.1f, %.1f) m  warnings %zu\n", name,
                    chest_eval::walking_steps(r.steps), d, chest_eval::mag_used_pct(r.attitudes), last.pos_enu_m[0],
                    last.pos_enu_m[1], r.warnings.size());
    }
    std::printf("\n");
}

void print_sims(const ChestSuiteSetup& s, const Preset& p) {
    for (bool calibrated : {false, true}) {
        std::string cfg = *p.json;
        if (calibrated) {
            const chest_eval::Calibrated c =
                chest_eval::calibrate_on_sims(cfg, p.mount, {calibration_sim(p.mount)}, s.plugin_dirs);
            cfg = c.config_json;
            std::printf("simulated %s walks, %s calibrated on corridor_loop seed 9: %s\n", p.mount, p.label.c_str(),
                        c.summary.c_str());
        } else {
            std::printf("simulated %s walks, %s as is\n", p.mount, p.label.c_str());
        }
        std::printf("  %-14s %4s %6s %6s %6s %7s %9s %8s %7s %7s\n", "route", "seed", "mean", "p75", "max", "floor%",
                    "closure", "dist err", "steps", "mag%");
        std::vector<double> floors, dist, p75s;
        for (const std::string& route : kSimRoutes)
            for (int seed = 1; seed <= kSeeds; ++seed) {
                eval::SimulatedWalk w;
                for (const eval::SimulatedWalk& b : eval::builtin_sim_walks(p.mount, static_cast<uint64_t>(seed)))
                    if (b.route == route) w = b;
                const WalkScore r = chest_eval::score_sim(w, cfg, s.plugin_dirs);
                const eval::Metrics& m = r.metrics;
                std::printf("  %-14s %4d %6.2f %6.2f %6.2f %7.1f %7.2f m %+7.1f%% %3zu/%3zu %7.1f\n", route.c_str(), seed,
                            m.horizontal_m.mean, m.horizontal_m.p75, m.horizontal_m.max, m.floor_correct_pct,
                            r.closure_m, r.distance_error_pct, r.steps, r.true_steps, r.mag_used_pct);
                floors.push_back(m.floor_correct_pct);
                dist.push_back(std::fabs(r.distance_error_pct));
                p75s.push_back(m.horizontal_m.p75);
            }
        std::printf("  spread over %zu walks: floor right min %.1f %% median %.1f %%; |distance error| median %.1f %% "
                    "worst %.1f %%; p75 median %.2f m worst %.2f m\n\n",
                    floors.size(), *std::min_element(floors.begin(), floors.end()), median(floors), median(dist),
                    worst(dist), median(p75s), worst(p75s));
    }
}

void print_rates(const ChestSuiteSetup& s, const Preset& p) {
    std::printf("%s, %s walks: steps on corridor_loop by IMU rate and sample-time jitter (seed 1)\n",
                p.label.c_str(), p.mount);
    for (double rate : {50.0, 100.0, 200.0, 500.0})
        for (double jitter_fraction : {0.0, 0.4}) {
            eval::SimulatedWalk w = eval::builtin_sim_walks(p.mount, 1).front();
            w.rate_hz = rate;
            w.time_jitter_s = jitter_fraction / rate;
            const WalkScore r = chest_eval::score_sim(w, *p.json, s.plugin_dirs);
            std::printf("  %5.0f Hz jitter %4.1f ms: steps %3zu / %3zu, distance error %+5.1f %%, mean error %.2f m\n", rate,
                        1e3 * w.time_jitter_s, r.steps, r.true_steps, r.distance_error_pct, r.metrics.horizontal_m.mean);
        }
    std::printf("\n");
}

}  // namespace

void run_chest_suite(const ChestSuiteSetup& s) {
    // The paper's step displacement on the chest pipeline, for comparison.
    const std::string step_vector = eval::patched_config(
        s.chest_preset_json, {{"pipelines", {{"chest", {{"position_filter", {{"plugin", "org.pednav.pdr.step_vector"}}}}}}}});
    const Preset handheld{"handheld preset", "handheld", &s.handheld_preset_json};
    const Preset chest{"chest preset", "chest", &s.chest_preset_json};
    const Preset vector{"chest preset with the step vector", "chest", &step_vector};
    for (const Preset* p : {&handheld, &chest, &vector}) print_humolire(s, *p);
    for (const Preset* p : {&chest, &vector, &handheld}) print_biba(s, *p);
    for (const Preset* p : {&handheld, &chest, &vector}) print_sims(s, *p);
    for (const Preset* p : {&handheld, &chest}) print_rates(s, *p);
}

}  // namespace pednav::cli
