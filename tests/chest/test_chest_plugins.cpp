// SPDX-License-Identifier: Apache-2.0
// The chest and handheld plugins' contracts through the real loader: a sensor
// that does not point the way the walker goes, the magnetometer flag, the
// app's attitude, parameter errors, determinism.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include <pednav/pn_engine.h>
#include <pednav_chest_eval/walk_scores.hpp>
#include <pednav_engine/replay.hpp>
#include <pednav_eval/track.hpp>
#include <pednav_eval/truth_readers.hpp>
#include <pednav_sim/simulate.hpp>

#include "test_support.hpp"

using namespace pednav;
using namespace pednav::test;

namespace {

// A simulated walk without a start heading from the app: the heading comes
// from the magnetometer (the simulator's declination given to the attitude
// estimator). Mean horizontal error after the start point, m.
double mean_error_without_heading(const std::string& config_json, eval::SimulatedWalk w) {
    const sim::Route route = eval::sim_route(w);
    const sim::SimOutput out = sim::simulate(route, eval::sim_options(w));
    nlohmann::json doc = nlohmann::json::parse(config_json);
    doc["pipelines"]["chest"]["attitude_estimator"]["params"]["declination_deg"] = sim::SimOptions{}.declination_deg;
    ReplayOptions o;
    o.config_json = doc.dump();
    o.plugin_dirs = kPlugins;
    const ReplayResult r = replay(o, out.records());
    REQUIRE(r.error.empty());
    eval::EvalOptions eo;
    eo.alignment = eval::Alignment::start_point;
    return eval::evaluate(eval::track_from_positions(r.positions), eval::sim_truth(out, route), eo).horizontal_m.mean;
}

std::string engine_error(const std::string& config_json) {
    ReplayOptions o;
    o.config_json = config_json;
    o.plugin_dirs = kPlugins;
    return config_problem(o);
}

}  // namespace

TEST_CASE("chest preset: the walking direction is learnt, so the sensor may point any way") {
    const std::string learnt = preset("chest");
    const std::string fixed_x = preset("chest", {{"forward_axis", "x"}, {"learn_offset_steps", 0}});
    for (double yaw : {0.0, 90.0, 180.0}) {
        CAPTURE(yaw);
        eval::SimulatedWalk w = sim_walk("chest", "corridor_loop");
        w.mounting_rpy_deg[2] = yaw;
        const double e_learnt = mean_error_without_heading(learnt, w);
        CHECK(e_learnt < 3.0);
        if (yaw != 0.0) CHECK(mean_error_without_heading(fixed_x, w) > 10.0);
    }
    // Pitched nearly vertical (the biba sensor's x axis points up).
    eval::SimulatedWalk up = sim_walk("chest", "corridor_loop");
    up.mounting_rpy_deg[1] = -80;
    CHECK(mean_error_without_heading(learnt, up) < 3.0);
}

TEST_CASE("madgwick: PN_ATTITUDE_FLAG_MAG_USED only while the field agrees with the local one") {
    // building_tour has disturbances at the lift shaft and radiators: some readings are refused.
    const ReplayResult disturbed = [] {
        eval::SimulatedWalk w = sim_walk("handheld", "building_tour");
        const sim::SimOutput out = sim::simulate(eval::sim_route(w), eval::sim_options(w));
        ReplayOptions o;
        o.config_json = preset("handheld");
        o.plugin_dirs = kPlugins;
        o.keep_attitudes = true;
        return replay(o, out.records());
    }();
    const double used = chest_eval::mag_used_pct(disturbed.attitudes);
    CHECK(used > 95.0);
    CHECK(used < 99.9);
    // Without a magnetometer, or in the IMU form, never.
    eval::SimulatedWalk w = sim_walk("handheld", "corridor_loop");
    sim::SimOptions so = eval::sim_options(w);
    so.with_mag = false;
    const sim::SimOutput out = sim::simulate(eval::sim_route(w), so);
    ReplayOptions o;
    o.config_json = preset("handheld");
    o.plugin_dirs = kPlugins;
    o.keep_attitudes = true;
    const ReplayResult r = replay(o, out.records());
    REQUIRE(!r.attitudes.empty());
    CHECK(chest_eval::mag_used_pct(r.attitudes) == 0.0);
    const sim::SimOutput with_mag = sim::simulate(eval::sim_route(w), eval::sim_options(w));
    o.config_json = eval::patched_config(
        preset("handheld"), {{"pipelines", {{"handheld", {{"attitude_estimator", {{"params", {{"form", "imu"}}}}}}}}}});
    CHECK(chest_eval::mag_used_pct(replay(o, with_mag.records()).attitudes) == 0.0);
}

TEST_CASE("madgwick: the app's attitude (pn_engine_set_attitude) is the start") {
    const std::string cfg = preset("handheld");
    const char* dirs[] = {PEDNAV_PLUGIN_OUTPUT_DIR};
    pn_engine_create_info_t info{};
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = cfg.c_str();
    info.plugin_dirs = dirs;
    info.plugin_dir_count = 1;
    pn_error_t err{};
    err.struct_size = sizeof err;
    pn_engine_t* engine = nullptr;
    REQUIRE_MESSAGE(pn_engine_create(&info, &engine, &err) == PN_OK, err.message);
    // Level, body x pointing west (heading -90 deg): a yaw of 180 deg from east.
    const double q[4] = {0.0, 0.0, 0.0, 1.0};
    REQUIRE(pn_engine_set_attitude(engine, q, &err) == PN_OK);
    pn_imu_t imu[3]{};
    for (int k = 0; k < 3; ++k) {
        imu[k].header.struct_size = sizeof(pn_imu_t);
        imu[k].header.type = PN_REC_IMU;
        imu[k].header.t_ns = (k + 1) * 10000000LL;
        imu[k].accel_mps2[2] = 9.81;
    }
    REQUIRE(pn_engine_set_output_mask(engine, PN_REC_MASK(PN_REC_ATTITUDE)) == PN_OK);
    REQUIRE(pn_engine_push_imu(engine, imu, 3, sizeof(pn_imu_t), &err) == PN_OK);
    REQUIRE(pn_engine_flush(engine, &err) == PN_OK);
    pn_output_t out;
    REQUIRE(pn_engine_poll(engine, &out) == PN_OK);
    REQUIRE(out.header.type == PN_REC_ATTITUDE);
    CHECK(std::fabs(out.attitude.q_enu_from_body[3]) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(std::fabs(out.attitude.heading_rad) == doctest::Approx(M_PI / 2).epsilon(1e-6));
    CHECK((out.attitude.header.flags & PN_ATTITUDE_FLAG_MAG_USED) == 0);
    pn_engine_destroy(engine);
}

TEST_CASE("chest plugins: parameter errors name the key, a run is reproducible") {
    CHECK(engine_error(preset("chest", {{"forward_axis", "auto"}, {"learn_offset_steps", 0}})).find("forward_axis") !=
          std::string::npos);
    const std::string bad_steps = eval::patched_config(
        preset("handheld"),
        {{"pipelines", {{"handheld", {{"step_detector", {{"params", {{"min_step_s", 0.8}, {"max_step_s", 0.5}}}}}}}}}});
    CHECK(engine_error(bad_steps).find("max_step_s") != std::string::npos);
    CHECK(engine_error(preset("handheld", {{"step_model_k", -1.0}})).find("step_model_k") != std::string::npos);
    CHECK(engine_error(preset("handheld")).empty());
    CHECK(engine_error(preset("chest")).empty());

    eval::SimulatedWalk w = sim_walk("handheld", "stairs");
    const sim::SimOutput out = sim::simulate(eval::sim_route(w), eval::sim_options(w));
    ReplayOptions o;
    o.config_json = preset("handheld");
    o.plugin_dirs = kPlugins;
    const ReplayResult a = replay(o, out.records()), b = replay(o, out.records());
    REQUIRE(a.positions.size() == b.positions.size());
    REQUIRE(!a.positions.empty());
    CHECK(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(pn_position_t)) == 0);
    // Stairs: the strides on them are classed so, and the floor goes up and comes back.
    size_t up = 0, down = 0;
    int top = 0;
    for (const pn_stride_t& s : a.strides) up += s.stride_class == PN_STRIDE_CLASS_STAIRS_UP, down += s.stride_class == PN_STRIDE_CLASS_STAIRS_DOWN;
    for (const pn_position_t& p : a.positions) top = std::max(top, p.floor);
    CHECK(up > 10);
    CHECK(down > 10);
    CHECK(top == 1);
    CHECK(a.positions.back().floor == 0);
}
