// SPDX-License-Identifier: Apache-2.0
// What pednav sim writes is what the engine's reader reads back.
#include <doctest/doctest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

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
