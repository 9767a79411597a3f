// SPDX-License-Identifier: Apache-2.0
#include "waist_report_suite.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <pednav_eval/metrics.hpp>
#include <pednav_sim/route.hpp>
#include <pednav_sim/simulate.hpp>
#include <pednav_waist_eval/ipol_scores.hpp>
#include <pednav_waist_eval/sim_scores.hpp>
#include <pednav_waist_eval/step_models.hpp>

namespace pednav::cli {

namespace {

void print_spread(const char* what, std::vector<double> v) {
    std::printf("%s: mean %.2f median %.2f worst %.2f (%zu)\n", what,
                v.empty() ? NAN : [&] {
                    double s = 0;
                    for (double x : v) s += x;
                    return s / v.size();
                }(),
                eval::percentile(v, 50), eval::percentile(v, 100), v.size());
}

sim::SimOptions waist_options(uint64_t seed, bool gnss) {
    sim::SimOptions o;
    o.mount = "waist";
    o.rate_hz = 100.0;
    o.seed = seed;
    o.with_gnss = gnss;
    o.baro_rate_hz = 25.0;
    o.mag_rate_hz = 50.0;
    return o;
}

void run_ipol(const std::vector<waist_eval::IpolTrial>& trials, const std::string& waist, const std::string& data_dir,
              const std::vector<std::string>& plugin_dirs) {
    std::vector<double> step_diff, uturn_err;
    for (const waist_eval::IpolTrial& t : trials) {
        const waist_eval::IpolWaistRun& r = t.run;
        std::printf("ipol %-5s steps %2d footsteps %2d  U-turn %6.1f deg\n", t.trial.c_str(), r.steps, r.footsteps,
                    r.uturn_deg);
        step_diff.push_back(std::abs(r.steps - r.footsteps));
        uturn_err.push_back(std::abs(r.uturn_deg - 180.0));
    }
    print_spread("ipol |steps - footsteps|", step_diff);
    print_spread("ipol |U-turn - 180| deg", uturn_err);

    std::vector<double> rel, legs;
    for (const waist_eval::LosoLeg& l : waist_eval::leave_one_subject_out(trials, data_dir, waist, plugin_dirs, 4.0)) {
        const double e = 100.0 * (l.waist_m / l.foot_m - 1.0);
        std::printf("ipol %-5s %-4s waist %6.2f m  foot %6.2f m  %+6.1f %%  (k %.3f without subject %s)\n",
                    l.trial.c_str(), l.out ? "out" : "back", l.waist_m, l.foot_m, e, l.k, l.subject.c_str());
        rel.push_back(std::abs(e));
        legs.push_back(l.waist_m);
    }
    print_spread("ipol legs |waist / foot - 1| %", rel);
    print_spread("ipol legs, m (protocol 10 m)", legs);
}

void run_step_models(const std::vector<waist_eval::IpolTrial>& trials) {
    std::vector<double> rise_cm;
    for (const auto& t : trials)
        for (const auto* steps : {&t.run.out_steps, &t.run.back_steps})
            for (const waist_eval::IpolStep& st : *steps) rise_cm.push_back(100.0 * st.pelvis_rise_m);
    std::printf("ipol step models: pelvis rise per step, cm: 5th percentile %.1f, median %.1f, 95th %.1f (%zu steps)\n",
                eval::percentile(rise_cm, 5), eval::percentile(rise_cm, 50), eval::percentile(rise_cm, 95),
                rise_cm.size());
    const auto summary = [](const std::vector<double>& e_pct) {
        std::vector<double> a;
        int within = 0;
        double sum = 0;
        for (double e : e_pct) a.push_back(std::abs(e)), within += std::abs(e) <= 5.0, sum += std::abs(e);
        char buf[160];
        std::snprintf(buf, sizeof buf, "mean %.1f %% median %.1f %% worst %.1f %%, %d of %zu within 5 %%",
                      a.empty() ? NAN : sum / a.size(), eval::percentile(a, 50), eval::percentile(a, 100), within,
                      a.size());
        return std::string(buf);
    };
    // A height the dataset lacks (subject 10) is the preset's user_height_m.
    for (const waist_eval::StepModelScores& m : waist_eval::score_step_models(trials, 1.7)) {
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (const auto& [subject, c] : m.constant_by_subject) lo = std::min(lo, c), hi = std::max(hi, c);
        std::printf("ipol step model %s\n  other subjects: %s\n  own legs: %s\n  other trial: %s\n"
                    "  first constant per subject (own legs) %.3f to %.3f (+%.0f %%):",
                    m.name.c_str(), summary(m.loso_error_pct).c_str(), summary(m.own_error_pct).c_str(),
                    summary(m.other_trial_error_pct).c_str(), lo, hi, 100.0 * (hi / lo - 1.0));
        for (const auto& [subject, c] : m.constant_by_subject) std::printf(" %s %.3f", subject.c_str(), c);
        std::printf("\n");
    }
}

void run_loop(const std::string& waist, const std::vector<std::string>& plugin_dirs, uint64_t seeds) {
    std::vector<double> closures;
    const sim::Route loop = sim::builtin_route("corridor_loop");
    for (uint64_t seed = 1; seed <= seeds; ++seed) {
        const sim::SimOutput out = sim::simulate(loop, waist_options(seed, false));
        const auto errors =
            waist_eval::output_errors(waist_eval::run_sim_waist(out, loop, waist, plugin_dirs), out);
        const double pct = errors.empty() ? NAN : 100.0 * errors.back().err_h_m / out.distance_m;
        std::printf("sim corridor_loop seed %llu  closure %.2f %% of %.0f m (no GNSS)\n",
                    static_cast<unsigned long long>(seed), pct, out.distance_m);
        closures.push_back(pct);
    }
    print_spread("sim corridor_loop closure %", closures);
}

void run_outage(const sim::Route& route, const std::string& waist,
                const std::vector<std::string>& plugin_dirs, uint64_t seeds) {
    const bool block = route.name == waist_eval::block_laps_route().name;
    std::vector<double> drift, without_scale, gnss_err, nees;
    int above_accuracy = 0;
    for (uint64_t seed = 1; seed <= seeds; ++seed) {
        sim::SimOutput out = sim::simulate(route, waist_options(seed, true));
        if (block)
            waist_eval::remove_fixes(out, waist_eval::kBlockOutageStartS, waist_eval::kBlockOutageEndS);
        const ReplayResult result = waist_eval::run_sim_waist(out, route, waist, plugin_dirs);
        const auto errors = waist_eval::output_errors(result, out);
        const auto gap = waist_eval::longest_gnss_gap_s(out.gnss);
        const waist_eval::Drift d = waist_eval::drift_in(errors, gap.first, gap.second);
        int n = 0;
        const double err = waist_eval::mean_error_of(errors, PN_POSITION_SOURCE_GNSS, &n);
        const double accuracy = waist_eval::mean_h_accuracy_m(out.gnss);
        const double t_fix0_s = out.gnss.empty() ? 0.0 : static_cast<double>(out.gnss.front().header.t_ns) * 1e-9;
        std::printf(
            "sim %-14s seed %llu  outage %.0f s, %.0f m: drift %.2f m (%.2f %%); GNSS mode error %.2f m "
            "(fixes' h_accuracy %.2f m, their own error %.2f m, %.2f m in their first 10 s), its NEES per axis %.2f\n",
            route.name.c_str(), static_cast<unsigned long long>(seed), gap.second - gap.first, d.walked_m,
            d.max_m, 100.0 * d.max_m / d.walked_m, err, accuracy, waist_eval::mean_fix_error_m(out, route),
            waist_eval::mean_fix_error_m(out, route, t_fix0_s, t_fix0_s + 10.0),
            waist_eval::mean_nees_per_axis_of(errors, PN_POSITION_SOURCE_GNSS));
        // Where the drift comes from: the track's scale and rotation
        // against the truth over the outage, and the true step length in
        // it against the 30 s of fixes before it (what GNSS taught).
        const double step_before_m = waist_eval::true_step_length_m(out, gap.first - 30.0, gap.first),
                     step_in_m = waist_eval::true_step_length_m(out, gap.first, gap.second);
        std::printf(
            "    its sources: track scale %+.2f %%, rotation %+.2f deg; without the scale %.2f %%; true step "
            "%.3f m in the outage, %.3f m in the 30 s before (%+.2f %%); learnt steps in the outage %+.2f %% "
            "against the true\n",
            d.scale_pct, d.rotation_deg, 100.0 * d.max_without_scale_m / d.walked_m, step_in_m, step_before_m,
            100.0 * (step_in_m / step_before_m - 1.0),
            waist_eval::stride_length_error_pct(result, out, gap.first, gap.second));
        // The GNSS-mode error on either side of the outage, with the fixes' own there.
        const auto gnss_error_between = [&](double t0_s, double t1_s) {
            double sum = 0;
            int count = 0;
            for (const waist_eval::OutputError& e : errors)
                if (e.source == PN_POSITION_SOURCE_GNSS && e.t_s > t0_s && e.t_s < t1_s)
                    sum += e.err_h_m, ++count;
            return count ? sum / count : NAN;
        };
        std::printf(
            "    GNSS mode error before the outage %.2f m (the fixes' own %.2f m), after it %.2f m (%.2f "
            "m)\n",
            gnss_error_between(-HUGE_VAL, gap.first),
            waist_eval::mean_fix_error_m(out, route, -HUGE_VAL, gap.first),
            gnss_error_between(gap.second, HUGE_VAL),
            waist_eval::mean_fix_error_m(out, route, gap.second, HUGE_VAL));
        drift.push_back(100.0 * d.max_m / d.walked_m);
        without_scale.push_back(100.0 * d.max_without_scale_m / d.walked_m);
        gnss_err.push_back(err);
        nees.push_back(waist_eval::mean_nees_per_axis_of(errors, PN_POSITION_SOURCE_GNSS));
        above_accuracy += err >= accuracy;
    }
    print_spread(("sim " + route.name + " outage drift %").c_str(), drift);
    print_spread(("sim " + route.name + " outage drift without the track's scale %").c_str(), without_scale);
    print_spread(("sim " + route.name + " GNSS mode error m").c_str(), gnss_err);
    print_spread(("sim " + route.name + " GNSS mode NEES per axis").c_str(), nees);
    std::printf("sim %s GNSS mode error at or above the fixes' h_accuracy: %d of %zu seeds\n",
                route.name.c_str(), above_accuracy, gnss_err.size());
}

void run_stairs(const std::string& waist, const std::vector<std::string>& plugin_dirs, uint64_t seeds) {
    const sim::Route stairs = sim::builtin_route("stairs");
    for (uint64_t seed = 1; seed <= seeds; ++seed) {
        const sim::SimOutput out = sim::simulate(stairs, waist_options(seed, false));
        const waist_eval::StairsScore s =
            waist_eval::stairs_score(waist_eval::run_sim_waist(out, stairs, waist, plugin_dirs), out);
        std::printf("sim stairs seed %llu  up %d/%d  down %d/%d  level labelled stairs %d/%d\n",
                    static_cast<unsigned long long>(seed), s.up_labelled_up, s.up_steps, s.down_labelled_down,
                    s.down_steps, s.level_labelled_stairs, s.level_steps);
    }
}

}  // namespace

void run_waist_suite(const std::string& waist, const std::string& foot, const std::string& data_dir,
                     const std::vector<std::string>& plugin_dirs, uint64_t seeds, const std::string& only) {
    const auto wanted = [&](const std::string& name) {
        return only.empty() || name.find(only) != std::string::npos;
    };
    if (wanted("ipol") || wanted("ipol step models")) {
        const auto trials = waist_eval::ipol_trials(data_dir, waist, foot, plugin_dirs);
        if (wanted("ipol")) run_ipol(trials, waist, data_dir, plugin_dirs);
        if (wanted("ipol step models")) run_step_models(trials);
    }
    if (wanted("corridor_loop")) run_loop(waist, plugin_dirs, seeds);
    const sim::Route oi = sim::builtin_route("outdoor_indoor"), block = waist_eval::block_laps_route();
    for (const sim::Route* route : {&oi, &block})
        if (wanted(route->name)) run_outage(*route, waist, plugin_dirs, seeds);
    if (wanted("stairs")) run_stairs(waist, plugin_dirs, seeds);
}

}  // namespace pednav::cli
