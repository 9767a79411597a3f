// SPDX-License-Identifier: Apache-2.0
// Every reader against the values its folder's SOURCE.md states: sample
// counts, durations, rates, units (via gravity at rest and known rows), axes.
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "pednav_io/sensor_log.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

constexpr double kG = 9.80665;
constexpr double kDeg = 0.017453292519943295;

// The recordings these tests read are part of the test suite: a missing
// folder fails the test, naming it (PEDNAV_SHARED_DATA_DIR sets where).
bool have_data(const std::string& folder) {
    if (exists(data_dir() + "/" + folder)) return true;
    FAIL_CHECK("shared recordings not found at " << data_dir() << "/" << folder
                                                 << " (configure with -DPEDNAV_SHARED_DATA_DIR=...)");
    return false;
}

const StreamInfo& stream_of(const SensorLog& log, const char* name) {
    const StreamInfo* s = log.stream(name);
    REQUIRE_MESSAGE(s != nullptr, "stream " << name << " missing in " << log.path);
    return *s;
}

}  // namespace

TEST_CASE("xio-gait-ngimu: 400 Hz NGIMU, deg/s and g, duplicate timestamps dropped") {
    if (!have_data("xio-gait-ngimu")) return;
    struct Case {
        const char* file;
        size_t rows, duplicates;
        double duration_s;
    };
    // SOURCE.md: short_walk 16 539 rows / ~41.6 s with 205 dt = 0; long_walk 28 132 rows / ~70.7 s with 252.
    for (const Case c : {Case{"short_walk.csv", 16539, 205, 41.6}, Case{"long_walk.csv", 28132, 252, 70.7}}) {
        CAPTURE(c.file);
        const SensorLog log = read_sensor_file(data_dir() + "/xio-gait-ngimu/" + c.file);
        CHECK(log.format == "xio-ngimu-csv");
        CHECK(log.imu.size() == c.rows - c.duplicates);
        CHECK(has_issue(log, log.issues.empty() ? 0 : log.issues.front().line,
                        std::to_string(c.duplicates) + " samples with a repeated timestamp dropped"));
        const StreamInfo& accel = stream_of(log, "accel");
        CHECK(accel.units_found == "g");
        CHECK(accel.units_converted == "m/s^2");
        CHECK(stream_of(log, "gyro").units_found == "deg/s");
        CHECK(accel.duration_s == doctest::Approx(c.duration_s).epsilon(0.005));
        CHECK(accel.median_rate_hz == doctest::Approx(398.0).epsilon(0.01));  // median dt 2.51 ms
        CHECK(accel.gaps == 0);
        CHECK(log.mag.empty());  // no magnetometer, no barometer
        CHECK(log.baro.empty());
        CHECK(log.imu.front().header.t_ns == 0);  // time starts at 0
        double a0[3];
        mean_accel(log, 50, a0);
        CHECK(norm3(a0) == doctest::Approx(kG).epsilon(0.02));                     // ~1.00 g at the start
        CHECK(max_gyro_norm(log) / kDeg == doctest::Approx(630.0).epsilon(0.25));  // peaks ~630 deg/s
        CHECK(max_accel_norm(log) / kG == doctest::Approx(5.0).epsilon(0.3));      // peaks ~5 g
    }
    // First row of short_walk: 0,-0.1428319,-0.7708032,-0.2320606,-0.4937814,0.2420433,0.8312204
    const SensorLog log = read_sensor_file(data_dir() + "/xio-gait-ngimu/short_walk.csv");
    CHECK(log.imu[0].gyro_radps[0] == doctest::Approx(-0.1428319 * kDeg));
    CHECK(log.imu[0].gyro_radps[1] == doctest::Approx(-0.7708032 * kDeg));
    CHECK(log.imu[0].accel_mps2[0] == doctest::Approx(-0.4937814 * kG));
    CHECK(log.imu[0].accel_mps2[2] == doctest::Approx(0.8312204 * kG));
}

TEST_CASE("koroglu-foot-gcp: SensorConnect layouts A (g, gauss) and B (m/s^2, :valid)") {
    if (!have_data("koroglu-foot-gcp")) return;
    struct Case {
        int n;
        double rate_hz;
        size_t rows;
        double duration_s;
        bool layout_a;
    };
    // SOURCE.md table: rate, rows / duration, columns.
    const Case cases[] = {{33, 200, 11000, 55.0, true},
                          {35, 200, 6001, 30.0, true},
                          {39, 200, 20000, 100.0, true},
                          {42, 250, 28751, 115.0, false},
                          {44, 250, 16501, 66.0, false}};
    for (const Case& c : cases) {
        CAPTURE(c.n);
        const SensorLog log = read_sensor_file(data_dir() + "/koroglu-foot-gcp/SensorConnectData_" +
                                               std::to_string(c.n) + ".csv");
        CHECK(log.format == (c.layout_a ? "microstrain-sensorconnect-a" : "microstrain-sensorconnect-b"));
        CHECK(log.imu.size() == c.rows);
        const StreamInfo& accel = stream_of(log, "accel");
        CHECK(accel.rate_hz == doctest::Approx(c.rate_hz).epsilon(0.002));
        CHECK(accel.median_rate_hz == doctest::Approx(c.rate_hz).epsilon(0.01));
        CHECK(accel.duration_s == doctest::Approx(c.duration_s).epsilon(0.001));
        CHECK(accel.units_found == (c.layout_a ? "g" : "m/s^2"));
        CHECK(stream_of(log, "gyro").units_found == "rad/s");
        CHECK(accel.bad_rows == 0);
        CHECK(log.issues.empty());
        // Layout A has a magnetometer in gauss, layout B none.
        CHECK(log.mag.size() == (c.layout_a ? c.rows : 0u));
        if (c.layout_a) {
            CHECK(stream_of(log, "mag").units_found == "gauss");
            const double m = norm3(log.mag[0].mag_ut);
            CHECK(m > 25.0);  // gauss * 100 = uT: an Earth-like field
            CHECK(m < 90.0);
        }
        double a0[3];
        mean_accel(log, 100, a0);
        // ~1.00 g at rest (A) / ~9.82 m/s^2 (B); case z points down, so body up (-z) is positive.
        CHECK(norm3(a0) == doctest::Approx(c.layout_a ? kG : 9.82).epsilon(0.02));
        CHECK(a0[2] > 0.5 * kG);
    }
    // Layout A at rest reads about (0.58, 0.16, -0.80) g in case axes: (0.58, -0.16, 0.80) g forward-left-up.
    const SensorLog log = read_sensor_file(data_dir() + "/koroglu-foot-gcp/SensorConnectData_33.csv");
    double a0[3];
    mean_accel(log, 100, a0);
    CHECK(a0[0] / kG == doctest::Approx(0.58).epsilon(0.1));
    CHECK(a0[1] / kG == doctest::Approx(-0.16).epsilon(0.4));
    CHECK(a0[2] / kG == doctest::Approx(0.80).epsilon(0.05));
}

TEST_CASE("ipol-gait-waist-feet: Xsens MTw tab-separated, PacketCounter / 100 Hz") {
    if (!have_data("ipol-gait-waist-feet")) return;
    // SOURCE.md "Trials taken": duration = rows of the lower-back file / 100 Hz.
    struct Case {
        const char* trial;
        double duration_s;
    };
    const Case cases[] = {{"1-1", 29.1},  {"1-2", 28.2},  {"5-1", 30.5},  {"5-2", 31.3},
                          {"10-1", 23.9}, {"10-2", 25.3}, {"15-1", 28.5}, {"19-1", 34.6}};
    for (const Case& c : cases) {
        for (const char* part : {"_lb", "_lf", "_rf"}) {
            const std::string path = data_dir() + "/ipol-gait-waist-feet/" + c.trial + part + ".txt";
            CAPTURE(path);
            const SensorLog log = read_sensor_file(path);
            CHECK(log.format == "xsens-mtw-tsv");
            const StreamInfo& accel = stream_of(log, "accel");
            CHECK(accel.median_rate_hz == doctest::Approx(100.0));  // "Acquisition frequency: 100 Hz"
            CHECK(accel.units_found == "m/s^2");
            CHECK(stream_of(log, "gyro").units_found == "rad/s");
            CHECK(stream_of(log, "mag").units_found == "normalised a.u.");
            CHECK(log.mag.size() == log.imu.size());
            CHECK(log.imu.front().header.t_ns <=
                  10000000);  // PacketCounter starts at 0 or 1 (t = counter / 100)
            CHECK(accel.bad_rows == 0);
            double a0[3];
            mean_accel(log, 100, a0);
            CHECK(norm3(a0) > 9.6);  // 9.8-10.2 at rest, not perfectly calibrated
            CHECK(norm3(a0) < 10.4);
            if (std::string(part) == "_lb") {
                CHECK(static_cast<double>(log.imu.size()) / 100.0 ==
                      doctest::Approx(c.duration_s).epsilon(0.003));
                // Lower-back peaks are about 2.5-3.5 rad/s.
                CHECK(max_gyro_norm(log) > 2.0);
                CHECK(max_gyro_norm(log) < 4.5);
            }
            // Normalised field ~0.8 a.u. scaled by 50 uT.
            double mag_mean = 0.0;
            for (const auto& m : log.mag) mag_mean += norm3(m.mag_ut) / static_cast<double>(log.mag.size());
            CHECK(mag_mean / 50.0 == doctest::Approx(0.8).epsilon(0.2));
        }
    }
    // 1-1 lower back at rest: about (8.2, 0.1, 5.9) m/s^2, gravity mostly on +X.
    const SensorLog lb = read_sensor_file(data_dir() + "/ipol-gait-waist-feet/1-1_lb.txt");
    double a0[3];
    mean_accel(lb, 200, a0);
    CHECK(a0[0] == doctest::Approx(8.2).epsilon(0.03));
    CHECK(std::fabs(a0[1]) < 0.4);
    CHECK(a0[2] == doctest::Approx(5.9).epsilon(0.04));
}

TEST_CASE("biba-chest-xsens: Xsens MT Manager CSV, SampleTimeFine in 100 us") {
    if (!have_data("biba-chest-xsens")) return;
    struct Case {
        const char* file;
        double duration_s;
    };
    for (const Case c : {Case{"kar_to_rita.txt", 96.5}, Case{"rita_to_kar.txt", 94.4},
                         Case{"K_calibration_test1-000.txt", 18.2}}) {
        CAPTURE(c.file);
        const SensorLog log = read_sensor_file(data_dir() + "/biba-chest-xsens/" + c.file);
        CHECK(log.format == "xsens-mtmanager-csv");
        const StreamInfo& accel = stream_of(log, "accel");
        CHECK(accel.duration_s == doctest::Approx(c.duration_s).epsilon(0.002));
        CHECK(accel.rate_hz == doctest::Approx(100.0).epsilon(1e-6));  // 100 ticks of 100 us, no gaps
        CHECK(accel.gaps == 0);
        CHECK(stream_of(log, "mag").units_found == "normalised a.u.");
        double a0[3];
        mean_accel(log, 100, a0);
        CHECK(a0[0] == doctest::Approx(9.7).epsilon(0.03));  // sensor X roughly vertical, ~+9.7 at rest
    }
    // rita_to_kar starts at tick 303336 and has 9 444 samples.
    const SensorLog log = read_sensor_file(data_dir() + "/biba-chest-xsens/rita_to_kar.txt");
    CHECK(log.imu.size() == 9444);
    CHECK(log.imu.front().header.t_ns == 30333600000LL);
}

TEST_CASE("merged_records: time order, IMU before MAG at equal time") {
    if (!have_data("koroglu-foot-gcp")) return;
    const SensorLog log = read_sensor_file(data_dir() + "/koroglu-foot-gcp/SensorConnectData_35.csv");
    const auto records = merged_records(log);
    REQUIRE(records.size() == log.imu.size() + log.mag.size());
    for (size_t i = 1; i < records.size(); ++i) {
        REQUIRE(records[i - 1]->t_ns <= records[i]->t_ns);
        if (records[i - 1]->t_ns == records[i]->t_ns) REQUIRE(records[i - 1]->type <= records[i]->type);
    }
    CHECK(records[0]->type == PN_REC_IMU);
    CHECK(records[1]->type == PN_REC_MAG);
    CHECK(records[0]->struct_size == sizeof(pn_imu_t));
    CHECK(records[1]->struct_size == sizeof(pn_mag_t));
}

TEST_CASE("biba-chest-xsens mapmatching_run/sensors.csv: the author's conversion of rita_to_kar undone") {
    if (!have_data("biba-chest-xsens")) return;
    const SensorLog converted =
        read_sensor_file(data_dir() + "/biba-chest-xsens/mapmatching_run/sensors.csv");
    const SensorLog raw = read_sensor_file(data_dir() + "/biba-chest-xsens/rita_to_kar.txt");
    CHECK(converted.format == "xsens-converted-g-csv");
    // SOURCE.md: same start tick 303336, same 9 444 samples; a = Acc / 9.70 with x/z swapped, gx = Gyr_Z.
    REQUIRE(converted.imu.size() == 9444);
    REQUIRE(raw.imu.size() == 9444);
    CHECK(converted.imu.front().header.t_ns == 30333600000LL);
    double worst_a = 0.0, worst_g = 0.0, worst_m = 0.0;
    for (size_t i = 0; i < raw.imu.size(); ++i) {
        REQUIRE(converted.imu[i].header.t_ns == raw.imu[i].header.t_ns);
        for (int k = 0; k < 3; ++k) {
            worst_a = std::max(worst_a, std::fabs(converted.imu[i].accel_mps2[k] - raw.imu[i].accel_mps2[k]));
            worst_g = std::max(worst_g, std::fabs(converted.imu[i].gyro_radps[k] - raw.imu[i].gyro_radps[k]));
            worst_m = std::max(worst_m, std::fabs(converted.mag[i].mag_ut[k] - raw.mag[i].mag_ut[k]));
        }
    }
    CHECK(worst_a < 1e-5);  // the file keeps 9 digits of g
    CHECK(worst_g < 1e-9);
    CHECK(worst_m < 1e-9);
    // p is hPa, 1016.38-1016.55 on a single floor.
    REQUIRE(converted.baro.size() == 9444);
    for (const auto& b : converted.baro) {
        REQUIRE(b.pressure_pa > 101637.0);
        REQUIRE(b.pressure_pa < 101656.0);
    }
    CHECK(stream_of(converted, "pressure").units_found == "hPa");
    CHECK(stream_of(converted, "accel").units_found == "g");
}

TEST_CASE("humolire-phone: two-file Android logs, ~418 Hz irregular, folder or either file") {
    if (!have_data("humolire-phone")) return;
    struct Case {
        const char* folder;
        size_t accel_rows, gyro_rows;
        double duration_s;
    };
    // SOURCE.md: durations 164 / 80 / 81 / 189 s; the streams differ by about 30 samples.
    const Case cases[] = {{"user1_straight", 68584, 68553, 164.0},
                          {"user1_8_shape", 33325, 33296, 80.0},
                          {"user1_square_2x", 33992, 33961, 81.0},
                          {"user3_forward", 78814, 78783, 189.0}};
    for (const Case& c : cases) {
        CAPTURE(c.folder);
        const std::string dir = data_dir() + "/humolire-phone/" + c.folder;
        const SensorLog log = read_sensor_file(dir);
        CHECK(log.format == "humolire-senslogs");
        const StreamInfo& accel = stream_of(log, "accel");
        const StreamInfo& gyro = stream_of(log, "gyro");
        CHECK(accel.count == c.accel_rows);
        CHECK(gyro.count == c.gyro_rows);
        CHECK(accel.count - gyro.count == doctest::Approx(30).epsilon(0.2));
        CHECK(accel.rate_hz == doctest::Approx(418.0).epsilon(0.005));        // "frequency": 418.0
        CHECK(accel.median_rate_hz == doctest::Approx(500.0).epsilon(0.01));  // median dt 2.0 ms
        CHECK(accel.duration_s == doctest::Approx(c.duration_s).epsilon(0.01));
        CHECK(log.imu.size() > c.gyro_rows - 5);  // paired on the accelerometer times within the gyro span
        CHECK(log.mag.empty());                   // no magnetometer, no barometer
        CHECK(log.baro.empty());
        double a0[3];
        mean_accel(log, 200, a0);
        CHECK(norm3(a0) == doctest::Approx(9.81).epsilon(0.05));  // m/s^2
        // Either file gives the same recording.
        const SensorLog via_gyro = read_sensor_file(dir + "/gyroscope-calibrated.txt");
        CHECK(via_gyro.imu.size() == log.imu.size());
        CHECK(via_gyro.imu.back().header.t_ns == log.imu.back().header.t_ns);
    }
}
