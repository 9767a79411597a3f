// SPDX-License-Identifier: Apache-2.0
// The walk list: the shared recordings it names exist with readable truths,
// and the simulated walks carry their settings to the simulator.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include <pednav_eval/walks.hpp>
#include <pednav_sim/simulate.hpp>

using namespace pednav::eval;

namespace {
const std::string kData = PEDNAV_SHARED_DATA_DIR;
bool exists(const std::string& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0;
}
}  // namespace

TEST_CASE("walk list: every shared recording with a truth exists and its truth reads") {
    const std::vector<RecordedWalk> walks = recorded_walks(kData);
    REQUIRE(walks.size() == 5 + 2 + 8 * 3 + 4);
    CHECK(walks.front().name == "koroglu-33");
    CHECK(walks[5].name == "xio-short_walk");
    CHECK(walks[7].name == "ipol-1-1-lf");
    CHECK(walks[9].name == "ipol-1-1-lb");
    CHECK(walks.back().name == "humolire-user3_forward");
    std::set<std::string> names;
    for (const RecordedWalk& w : walks) {
        CAPTURE(w.name);
        names.insert(w.name);
        CHECK(exists(w.input));
        if (w.truth_kind != TruthKind::loop) CHECK(exists(w.truth_path));
        const Truth t = read_walk_truth(w);
        CHECK(t.kind == w.truth_kind);
    }
    CHECK(names.size() == walks.size());
}

TEST_CASE("walk list: each dataset's mount, alignment, truth and sensor range") {
    const RecordedWalk k = koroglu_walk(kData, 35);
    CHECK(k.input == kData + "/koroglu-foot-gcp/SensorConnectData_35.csv");
    CHECK(k.truth_path == kData + "/koroglu-foot-gcp/SensorConnectData_35_gcp.csv");
    CHECK(k.alignment == Alignment::fitted);
    CHECK(k.gyro_range_radps == doctest::Approx(8.7266).epsilon(1e-4));  // 500 deg/s
    CHECK(read_walk_truth(k).step_count == 28);
    const RecordedWalk x = xio_walk(kData, "long_walk");
    CHECK(x.truth_kind == TruthKind::loop);
    CHECK(read_walk_truth(x).closed_loop);
    CHECK(x.gyro_range_radps == 0.0);
    const RecordedWalk lf = ipol_walk(kData, "5-2", "lf"), lb = ipol_walk(kData, "5-2", "lb");
    CHECK(lf.mount == "foot");
    CHECK(lf.feet == "left");
    CHECK(lb.mount == "waist");
    CHECK(lb.feet == "both");
    CHECK(read_walk_truth(lf).legs.size() == 2);
    CHECK_THROWS_WITH_AS(ipol_walk(kData, "5-2", "hand"), doctest::Contains("unknown part 'hand'"),
                         std::runtime_error);
    const RecordedWalk h = humolire_walk(kData, "user1_straight");
    CHECK(h.mount == "handheld");
    CHECK(h.give_start);
    CHECK(std::isfinite(read_walk_truth(h).start_heading_deg));
}

TEST_CASE("walk list: the simulated walks' settings reach the simulator") {
    SimulatedWalk w;
    w.route = "stairs";
    w.rate_hz = 256;
    w.seed = 7;
    w.error_scale = 5;
    w.accel_bias_walk_scale = 100;
    w.gyro_scale_errors = false;
    w.mounting_rpy_deg[1] = -30;
    w.gait = sweep_gaits().back();
    const pednav::sim::SimOptions defaults;
    const pednav::sim::SimOptions so = sim_options(w);
    CHECK(so.rate_hz == 256);
    CHECK(so.seed == 7);
    CHECK(so.mounting_rpy_deg[1] == -30);
    CHECK(so.imu.gyro_bias_radps == doctest::Approx(5 * defaults.imu.gyro_bias_radps));
    CHECK(so.imu.accel_bias_rw_mps2_per_rts == doctest::Approx(500 * defaults.imu.accel_bias_rw_mps2_per_rts));
    CHECK(so.imu.gyro_scale == 0.0);
    CHECK(so.heel_strike_g == 3.0);
    CHECK(!so.with_baro);
    CHECK(!so.with_gnss);
    const pednav::sim::Route r = sim_route(w);
    CHECK(r.speed_mps == 3.0);
    CHECK(r.step_length_m == 1.1);
    CHECK(r.stance_fraction == 0.12);
    SimulatedWalk unknown;
    unknown.route = "no_such_route";
    CHECK_THROWS_WITH_AS(sim_route(unknown), doctest::Contains("no_such_route"), std::runtime_error);
    // The report's: five built-in routes with the simulator's own defaults.
    const std::vector<SimulatedWalk> builtin = builtin_sim_walks("chest", 3);
    REQUIRE(builtin.size() == 5);
    CHECK(builtin.back().route == "outdoor_indoor");
    const pednav::sim::SimOptions b = sim_options(builtin.front());
    CHECK(b.mount == "chest");
    CHECK(b.seed == 3);
    CHECK(b.with_baro);
    CHECK(b.with_gnss);
    CHECK(b.imu.accel_bias_mps2 == defaults.imu.accel_bias_mps2);
}

TEST_CASE("walk list: the foot suites' grids") {
    const std::vector<SimulatedWalk> errors = imu_error_walks(400);
    REQUIRE(errors.size() == 10);
    CHECK(!errors[0].sensor_errors);
    CHECK(errors[2].error_scale == 5);
    CHECK(errors[4].accel_bias_walk_scale == 300);
    CHECK(errors[4].error_scale == 1);
    CHECK(errors[5].route == "stairs");
    CHECK(errors[9].rate_hz == 400);
    CHECK(errors[9].mounting_rpy_deg[0] == 20);
    const std::vector<SimulatedWalk> hupt = hupt_walks();
    REQUIRE(hupt.size() == 16);
    CHECK(hupt[3].seed == 4);
    CHECK(hupt[4].error_scale == 5);
    CHECK(hupt[8].route == "building_tour");
    const std::vector<SimulatedWalk> sweep = sweep_walks(false);
    REQUIRE(sweep.size() == 4 * 4 * 6 * 3);  // gaits x rates x mountings x seeds
    CHECK(!sweep.front().gyro_scale_errors);
    CHECK(std::string(sweep[18].gait.name) == "slow");
    CHECK(sweep[18].rate_hz == 200);  // a gait's rates one after the other, 18 runs each
    CHECK(std::string(sweep[72].gait.name) == "normal");
    CHECK(sweep.back().mounting_rpy_deg[2] == 120);
}
