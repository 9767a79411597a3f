// SPDX-License-Identifier: Apache-2.0
// What pednav sim writes is what the engine's reader reads back.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <pednav_io/gnss_log.hpp>
#include <pednav_io/sensor_log.hpp>
#include <pednav_sim/simulate.hpp>

using namespace pednav::sim;

TEST_CASE("input.csv: the canonical reader gets the simulated records back, multi-rate included") {
    SimOptions o;
    o.mag_rate_hz = 50.0;
    o.baro_rate_hz = 25.0;
    const Route route = builtin_route("stairs");
    const SimOutput out = simulate(route, o);
    CHECK(out.mag.size() == (out.imu.size() + 3) / 4);
    CHECK(out.baro.size() == (out.imu.size() + 7) / 8);
    const std::string dir = (std::filesystem::temp_directory_path() / ("pednav_sim_test_roundtrip_" + std::to_string(::getpid()))).string();
    write_outputs(out, route, dir);
    const pednav::io::SensorLog log = pednav::io::read_sensor_file(dir + "/input.csv");
    CHECK(log.format == "pednav-csv");
    REQUIRE(log.imu.size() == out.imu.size());
    REQUIRE(log.mag.size() == out.mag.size());
    REQUIRE(log.baro.size() == out.baro.size());
    double worst_a = 0, worst_g = 0, worst_m = 0, worst_p = 0;
    for (size_t k = 0; k < out.imu.size(); ++k) {
        CHECK(log.imu[k].header.t_ns == out.imu[k].header.t_ns);
        for (int i = 0; i < 3; ++i) {
            worst_a = std::max(worst_a, std::fabs(log.imu[k].accel_mps2[i] - out.imu[k].accel_mps2[i]));
            worst_g = std::max(worst_g, std::fabs(log.imu[k].gyro_radps[i] - out.imu[k].gyro_radps[i]));
        }
    }
    for (size_t k = 0; k < out.mag.size(); ++k) {
        CHECK(log.mag[k].header.t_ns == out.mag[k].header.t_ns);
        for (int i = 0; i < 3; ++i)
            worst_m = std::max(worst_m, std::fabs(log.mag[k].mag_ut[i] - out.mag[k].mag_ut[i]));
    }
    for (size_t k = 0; k < out.baro.size(); ++k)
        worst_p = std::max(worst_p, std::fabs(log.baro[k].pressure_pa - out.baro[k].pressure_pa));
    CHECK(worst_a < 1e-7);
    CHECK(worst_g < 1e-9);
    CHECK(worst_m < 1e-5);
    CHECK(worst_p < 1e-4);
    CHECK(log.issues.empty());
}

TEST_CASE("gnss.csv: the GNSS CSV reader gets the simulated fixes back") {
    const Route route = builtin_route("outdoor_indoor");
    const SimOutput out = simulate(route, SimOptions{});
    const std::string dir = (std::filesystem::temp_directory_path() /
                             ("pednav_sim_test_gnss_" + std::to_string(::getpid())))
                                .string();
    write_outputs(out, route, dir);
    const pednav::io::SensorLog log = pednav::io::read_gnss_file(dir + "/gnss.csv");
    CHECK(log.format == "csv");
    CHECK(log.issues.size() == 1);  // the gap indoors
    REQUIRE(log.gnss.size() == out.gnss.size());
    REQUIRE(out.gnss.size() == 119);
    double worst_deg = 0, worst_h = 0, worst_acc = 0, worst_vel = 0;
    for (size_t k = 0; k < out.gnss.size(); ++k) {
        const pn_gnss_t& a = log.gnss[k];
        const pn_gnss_t& b = out.gnss[k];
        CHECK(a.header.t_ns == b.header.t_ns);
        CHECK(a.satellites == b.satellites);
        CHECK(a.fix_type == b.fix_type);
        CHECK(a.header.flags == b.header.flags);
        worst_deg = std::max({worst_deg, std::fabs(a.lat_deg - b.lat_deg), std::fabs(a.lon_deg - b.lon_deg)});
        worst_h = std::max(worst_h, std::fabs(a.height_m - b.height_m));
        worst_acc = std::max({worst_acc, std::fabs(a.h_accuracy_m - b.h_accuracy_m),
                              std::fabs(a.v_accuracy_m - b.v_accuracy_m)});
        // Speed and course keep the horizontal velocity; the format has no vertical one.
        worst_vel = std::max({worst_vel, std::fabs(a.vel_enu_mps[0] - b.vel_enu_mps[0]),
                              std::fabs(a.vel_enu_mps[1] - b.vel_enu_mps[1])});
        CHECK(a.vel_enu_mps[2] == 0.0);
    }
    CHECK(worst_deg < 1e-9);
    CHECK(worst_h < 1e-3);
    CHECK(worst_acc < 1e-3);
    CHECK(worst_vel < 3e-3);
    std::filesystem::remove_all(dir);
}
