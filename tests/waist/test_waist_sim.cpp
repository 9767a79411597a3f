// SPDX-License-Identifier: Apache-2.0
// The waist pipeline on simulated waist walks with exact truth, through the
// real loader: a loop without GNSS, GNSS outages, fix quality that changes,
// a fix 50 m off, stairs. Routes the simulator lacks and the changes to the
// fixes are made here (docs/simulator.md, pednav-route/1).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <pednav_sim/route.hpp>
#include <pednav_sim/simulate.hpp>
#include <pednav_waist_eval/sim_scores.hpp>

using namespace pednav;
using waist_eval::OutputError;

namespace {
const std::vector<std::string> kPlugins = {PEDNAV_PLUGIN_OUTPUT_DIR};
const std::string& waist() {
    static const std::string cfg = waist_eval::waist_preset(PEDNAV_SOURCE_DIR);
    return cfg;
}
sim::SimOptions options(uint64_t seed, bool gnss) {
    sim::SimOptions o;
    o.mount = "waist";
    o.rate_hz = 100.0;
    o.seed = seed;
    o.with_gnss = gnss;
    o.baro_rate_hz = 25.0;
    o.mag_rate_hz = 50.0;
    return o;
}
using waist_eval::Drift;
using waist_eval::drift_in;
using waist_eval::mean_error_of;
std::pair<double, double> longest_gap_s(const std::vector<pn_gnss_t>& f) { return waist_eval::longest_gnss_gap_s(f); }
double mean_accuracy_m(const std::vector<pn_gnss_t>& f) { return waist_eval::mean_h_accuracy_m(f); }
int source_at(const std::vector<OutputError>& errors, double t_s) {
    int s = -1;
    for (const OutputError& e : errors)
        if (e.t_s <= t_s) s = e.source;
    return s;
}
// A fix moved east by `east_m`.
void move_east(pn_gnss_t& g, double east_m) {
    g.lon_deg += east_m / (6378137.0 * std::cos(g.lat_deg * M_PI / 180.0)) * 180.0 / M_PI;
}
}  // namespace

TEST_CASE("issue 14: simulated waist corridor loop closes within 2 % without GNSS") {
    const sim::Route route = sim::builtin_route("corridor_loop");
    std::vector<double> closures;
    for (uint64_t seed : {1, 2, 3}) {
        const sim::SimOutput out = sim::simulate(route, options(seed, false));
        const ReplayResult r = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
        const std::vector<OutputError> errors = waist_eval::output_errors(r, out);
        REQUIRE(!errors.empty());
        size_t steps = 0;
        for (const pn_step_t& s : r.steps) steps += s.motion_mode != PN_STEP_MODE_STATIC;
        const double closure_pct = 100.0 * errors.back().err_h_m / out.distance_m;
        CAPTURE(seed);
        CAPTURE(steps);
        CAPTURE(out.step_times_s.size());
        CAPTURE(closure_pct);
        CHECK(std::abs(static_cast<double>(steps) - static_cast<double>(out.step_times_s.size())) <= 2);
        CHECK(closure_pct < 2.0);
        for (const OutputError& e : errors) CHECK(e.source == PN_POSITION_SOURCE_INERTIAL);
        closures.push_back(closure_pct);
    }
    MESSAGE("corridor_loop without GNSS, 3 seeds: closure " << closures[0] << ", " << closures[1] << ", "
                                                            << closures[2] << " % of the distance");
}

TEST_CASE("issue 14: simulated outdoor_indoor: under the fixes' accuracy with GNSS, drift under 2 % in the outage") {
    const sim::Route route = sim::builtin_route("outdoor_indoor");
    std::vector<double> drift_pct, gnss_err;
    for (uint64_t seed : {1, 2, 3}) {
        const sim::SimOutput out = sim::simulate(route, options(seed, true));
        REQUIRE_MESSAGE(out.gnss.size() > 50, "the simulated walk has " << out.gnss.size() << " fixes");
        const ReplayResult r = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
        const std::vector<OutputError> errors = waist_eval::output_errors(r, out);
        int n_gnss = 0;
        const double err_gnss = mean_error_of(errors, PN_POSITION_SOURCE_GNSS, &n_gnss);
        const auto gap = longest_gap_s(out.gnss);
        const Drift d = drift_in(errors, gap.first, gap.second);
        CAPTURE(seed);
        CAPTURE(n_gnss);
        CAPTURE(err_gnss);
        CAPTURE(mean_accuracy_m(out.gnss));
        CAPTURE(gap.second - gap.first);
        CAPTURE(d.walked_m);
        CAPTURE(d.max_m);
        CHECK(n_gnss > 50);
        // Measured 0.83, 0.83, 1.02 m. Over seeds 1-32, 9 walks are above the
        // fixes' 2.24 m (seed 4: 2.33 m): their error is correlated over 60 s
        // and this walk has 58 s of fixes before the building and 59 s after
        // (docs/waist-pipeline.md). The outputs' covariance is the size of
        // their error (NEES per axis 0.25, 0.31, 0.42; 1.24 over seeds 1-32).
        CHECK(err_gnss < mean_accuracy_m(out.gnss));
        CHECK(waist_eval::mean_nees_per_axis_of(errors, PN_POSITION_SOURCE_GNSS) < 3.0);
        CHECK(d.walked_m > 70.0);
        // The target is 2 %; measured 1.55, 1.90 and 0.85 %. The learnt
        // step length follows the walker's 2.3 % longer steps indoors (+0.4,
        // +1.9, +0.2 % of the feet's steps over the outage; -3.1, -1.8, -3.5 %
        // while the simulated bounce did not grow with the step). The
        // simulated trunk rounds the two corners inside the building and, over
        // each corner's two steps, bounces as its own chord there (21 %
        // shorter than the feet's spacing) makes it: the fusion's steps there
        // are 5-10 % longer than the trunk's travel, not 25 %, and each corner
        // moves the track about 0.2 m, not 0.36 m (exact sensors, seed 1).
        // While the bounce followed the feet's spacing: 1.85, 2.09, 1.13 %
        // (seed 2 missed the target); with the trunk over every footprint
        // 1.80, 2.03, 1.08 %; with the steps read short 1.02, 0.83, 1.59 %.
        // docs/waist-pipeline.md, "Simulated waist walks".
        CHECK(d.max_m < 0.02 * d.walked_m);
        drift_pct.push_back(100.0 * d.max_m / d.walked_m);
        gnss_err.push_back(err_gnss);
        // Steps alone indoors, GNSS outdoors before and after.
        CHECK(source_at(errors, gap.first - 5.0) == PN_POSITION_SOURCE_GNSS);
        CHECK(source_at(errors, 0.5 * (gap.first + gap.second)) == PN_POSITION_SOURCE_INERTIAL);
        CHECK(source_at(errors, gap.second + 10.0) == PN_POSITION_SOURCE_GNSS);
    }
    MESSAGE("outdoor_indoor, 3 seeds: drift in the indoor outage " << drift_pct[0] << ", " << drift_pct[1] << ", "
                                                                   << drift_pct[2] << " % of the distance in it; "
                                                                   << "mean error with GNSS " << gnss_err[0] << ", "
                                                                   << gnss_err[1] << ", " << gnss_err[2] << " m");
}

TEST_CASE("issue 14: simulated outdoor_indoor: the mode follows the fixes' quality; a fix 50 m off is rejected") {
    const sim::Route route = sim::builtin_route("outdoor_indoor");
    sim::SimOutput out = sim::simulate(route, options(1, true));
    const auto gap = longest_gap_s(out.gnss);
    const ReplayResult clean = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
    // After the building: 15 s of poor fixes (8 m, errors to match), then
    // 10 s of fixes from 3 satellites (unusable), then good ones again; and
    // one fix 50 m east before the building.
    const double t_poor = gap.second + 5.0, t_few = t_poor + 15.0, t_good = t_few + 10.0;
    double t_jump = 0;
    for (pn_gnss_t& g : out.gnss) {
        const double t = g.header.t_ns * 1e-9;
        g.satellites = 9;
        if (t >= t_poor && t < t_few) {
            g.h_accuracy_m = 8.0;
            move_east(g, 4.0 * std::sin(t));
            g.satellites = 6;
        } else if (t >= t_few && t < t_good) {
            g.satellites = 3;
            move_east(g, 30.0);
        }
        if (t_jump == 0 && t > gap.first - 15.0) {
            move_east(g, 50.0);
            t_jump = t;
        }
    }
    const ReplayResult r = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
    const std::vector<OutputError> errors = waist_eval::output_errors(r, out);
    const std::vector<OutputError> clean_errors = waist_eval::output_errors(clean, out);
    CAPTURE(t_jump);
    CHECK(source_at(errors, gap.first - 2.0) == PN_POSITION_SOURCE_GNSS);
    CHECK(source_at(errors, 0.5 * (gap.first + gap.second)) == PN_POSITION_SOURCE_INERTIAL);
    CHECK(source_at(errors, t_poor + 8.0) == PN_POSITION_SOURCE_FUSED);
    CHECK(source_at(errors, t_few + 7.0) == PN_POSITION_SOURCE_INERTIAL);
    CHECK(source_at(errors, t_good + 8.0) == PN_POSITION_SOURCE_GNSS);
    // The jump: no output moves towards it.
    double worst_after_jump = 0;
    for (const OutputError& e : errors)
        if (e.t_s > t_jump && e.t_s < t_jump + 10.0) worst_after_jump = std::max(worst_after_jump, e.err_h_m);
    CAPTURE(worst_after_jump);
    CHECK(worst_after_jump < 6.0);
    // The unusable fixes (30 m off) do not move the track either.
    double worst_few = 0;
    for (const OutputError& e : errors)
        if (e.t_s > t_few && e.t_s < t_good + 3.0) worst_few = std::max(worst_few, e.err_h_m);
    CAPTURE(worst_few);
    CHECK(worst_few < 8.0);
    CHECK(clean_errors.size() == errors.size());
}

TEST_CASE("issue 14: simulated long outdoor walk with a 60 s GNSS outage: drift under 2 % of the distance in it") {
    const sim::Route route = waist_eval::block_laps_route();
    std::vector<double> drift_pct, gnss_err;
    for (uint64_t seed : {1, 2, 3}) {
        sim::SimOutput out = sim::simulate(route, options(seed, true));
        waist_eval::remove_fixes(out, waist_eval::kBlockOutageStartS, waist_eval::kBlockOutageEndS);
        const ReplayResult r = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
        const std::vector<OutputError> errors = waist_eval::output_errors(r, out);
        const auto gap = longest_gap_s(out.gnss);
        const Drift d = drift_in(errors, gap.first, gap.second);
        int n_gnss = 0;
        const double err_gnss = mean_error_of(errors, PN_POSITION_SOURCE_GNSS, &n_gnss);
        CAPTURE(seed);
        CAPTURE(d.walked_m);
        CAPTURE(d.max_m);
        CAPTURE(err_gnss);
        CHECK(gap.second - gap.first > 59.0);
        CHECK(d.walked_m > 70.0);
        // The target is 2 %; measured 0.90, 1.20 and 0.81 % (2.05,
        // 2.26 and 1.58 % before the magnetometer's compass deviation and
        // the fixes' correlated error were estimated, on the simulated walker
        // of the time).
        CHECK(d.max_m < 0.016 * d.walked_m);
        CHECK(err_gnss < mean_accuracy_m(out.gnss));
        CHECK(waist_eval::mean_nees_per_axis_of(errors, PN_POSITION_SOURCE_GNSS) < 3.0);
        drift_pct.push_back(100.0 * d.max_m / d.walked_m);
        gnss_err.push_back(err_gnss);
    }
    MESSAGE("60 s outage, 3 seeds: drift " << drift_pct[0] << ", " << drift_pct[1] << ", " << drift_pct[2]
                                           << " % of the distance in it; mean error with GNSS " << gnss_err[0]
                                           << ", " << gnss_err[1] << ", " << gnss_err[2] << " m");
}

TEST_CASE("issue 14: simulated stairs: steps labelled upstairs and downstairs from the barometer") {
    const sim::Route route = sim::builtin_route("stairs");
    for (uint64_t seed : {1, 2}) {
        const sim::SimOutput out = sim::simulate(route, options(seed, false));
        const ReplayResult r = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
        const waist_eval::StairsScore s = waist_eval::stairs_score(r, out);
        CAPTURE(seed);
        CAPTURE(s.up_steps);
        CAPTURE(s.up_labelled_up);
        CAPTURE(s.down_steps);
        CAPTURE(s.down_labelled_down);
        CAPTURE(s.level_steps);
        CAPTURE(s.level_labelled_stairs);
        CHECK(s.up_steps >= 15);
        CHECK(s.down_steps >= 15);
        CHECK(s.up_labelled_up >= 0.8 * s.up_steps);
        CHECK(s.down_labelled_down >= 0.8 * s.down_steps);
        CHECK(s.level_labelled_stairs <= 0.1 * s.level_steps);
        MESSAGE("stairs, seed " << seed << ": up " << s.up_labelled_up << " of " << s.up_steps << ", down "
                                << s.down_labelled_down << " of " << s.down_steps << ", level steps labelled stairs "
                                << s.level_labelled_stairs << " of " << s.level_steps);
    }
}

TEST_CASE("simulated building tour: turns on the spot in pauses keep the walking direction (no GNSS)") {
    // Stops at doors, turning on the spot before walking on: the turn made
    // while standing is applied before the next step, not spread over it.
    const sim::Route route = sim::builtin_route("building_tour");
    const sim::SimOutput out = sim::simulate(route, options(1, false));
    const ReplayResult r = waist_eval::run_sim_waist(out, route, waist(), kPlugins);
    double worst_deg = 0;
    for (const pn_position_t& p : r.positions) {
        const size_t i = std::min(out.truth.size() - 1, static_cast<size_t>(std::llround(p.header.t_ns * 1e-9 * out.rate_hz)));
        if (out.truth[i].stance) continue;  // standing: the truth's heading is the body's, mid-turn
        worst_deg = std::max(worst_deg, std::abs(std::remainder(p.heading_rad * 180 / M_PI - out.truth[i].heading_deg, 360.0)));
    }
    MESSAGE("building tour, walking direction against the truth at every step: worst " << worst_deg << " deg");
    CHECK(worst_deg < 5.0);  // measured 3.89 deg
}
