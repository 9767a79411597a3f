// SPDX-License-Identifier: Apache-2.0
// Formats exercised on files the tests write: the IPIN logfile and column maps.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pednav_io/sensor_log.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

TEST_CASE("IPIN logfile: streams merged by time, hPa, POSI as ground truth") {
    const std::string dir = temp_dir();
    std::ostringstream f;
    f.precision(10);
    f << "% LogFile created by the 'GetSensorData' App\n"
      << "% "
         "ACCE;AppTimestamp(s);SensorTimestamp(s);Acc_X(m/s^2);Acc_Y(m/s^2);Acc_Z(m/s^2);Accuracy(integer)\n"
      << "POSI;0.010;1;40.31360000;-3.48370000;0;0\n";
    // 50 Hz accelerometer and gyroscope for 4 s; sensor clock = app clock - 100 s, delivered 0-15 ms late.
    for (int i = 0; i < 200; ++i) {
        const double ts = 100.0 + i * 0.02;
        const double delay = 0.005 * (i % 4);
        f << "ACCE;" << ts - 100.0 + 0.001 + delay << ";" << ts << ";0.5;1.0;9.7;3\n";
        f << "GYRO;" << ts - 100.0 + 0.002 + delay << ";" << ts + 0.01 << ";0.01;0.02;0.03;3\n";
        if (i % 5 == 0) f << "MAGN;" << ts - 100.0 + 0.003 << ";" << ts << ";10;20;-40;3\n";
        if (i % 10 == 0) f << "PRES;" << ts - 100.0 + 0.004 << ";" << ts << ";1013.25;0\n";
        if (i % 50 == 0) f << "AHRS;" << ts - 100.0 << ";" << ts << ";1;2;3;0.1;0.2;0.3;3\n";
        if (i == 100) f << "WIFI;2.0;2.0;eduroam;00:11:22:33:44:55;2412;-70\n";
    }
    f << "GNSS;1.5;1700000000.5;40.3137;-3.4836;650.0;90.0;5.0;1.2;12;8\n";
    f << "GYRO;3.0;102.0;abc;0;0;3\n";                  // bad: text
    f << "POSI;3.990;2;40.31369000;-3.48370000;1;0\n";  // 10 m north, floor 1
    const std::string path = write_file(dir, "logfile.txt", f.str());
    const SensorLog log = read_sensor_file(path);
    CHECK(log.format == "ipin-logfile");
    // Accelerometer times: sensor clock + (smallest app - sensor) = i * 0.02 + 0.001; gyroscope i * 0.02 +
    // 0.002, so the first accelerometer sample precedes the gyroscope stream and is dropped.
    REQUIRE(log.imu.size() == 199);
    CHECK(log.stream("accel")->count == 200);
    CHECK(log.imu[0].header.t_ns == 21000000);
    CHECK(log.imu[10].header.t_ns == 221000000);
    // Android (x right, y up the screen, z out) to forward-left-up: (y, -x, z).
    CHECK(log.imu[0].accel_mps2[0] == doctest::Approx(1.0));
    CHECK(log.imu[0].accel_mps2[1] == doctest::Approx(-0.5));
    CHECK(log.imu[0].accel_mps2[2] == doctest::Approx(9.7));
    CHECK(log.imu[0].gyro_radps[0] == doctest::Approx(0.02));
    CHECK(log.imu[0].gyro_radps[1] == doctest::Approx(-0.01));
    REQUIRE(log.mag.size() == 40);
    CHECK(log.mag[0].mag_ut[0] == doctest::Approx(20.0));
    REQUIRE(log.baro.size() == 20);
    CHECK(log.baro[0].pressure_pa == doctest::Approx(101325.0));
    CHECK(log.stream("pressure")->units_found == "hPa");
    REQUIRE(log.gnss.size() == 1);
    CHECK(log.gnss[0].header.t_ns == 1500000000);
    CHECK(log.gnss[0].lat_deg == doctest::Approx(40.3137));
    CHECK(log.gnss[0].vel_enu_mps[0] == doctest::Approx(1.2));  // bearing 90 deg: east
    CHECK(std::fabs(log.gnss[0].vel_enu_mps[1]) < 1e-9);
    CHECK(log.gnss[0].h_accuracy_m == doctest::Approx(5.0));
    CHECK(log.gnss[0].header.flags == PN_GNSS_FLAG_HAS_VELOCITY);
    CHECK(log.gnss[0].header.type == PN_REC_GNSS);
    CHECK(log.gnss[0].utc_ns == 1700000000500000000LL);
    REQUIRE(log.truth.size() == 2);
    CHECK(log.truth[0].x_m == doctest::Approx(0.0));
    CHECK(log.truth[1].t_s == doctest::Approx(3.99));
    CHECK(log.truth[1].y_m == doctest::Approx(0.00009 * 111034.0).epsilon(0.002));  // ~10 m north
    CHECK(std::fabs(log.truth[1].x_m) < 1e-6);
    CHECK(log.truth[1].floor == 1);
    CHECK(log.truth[1].label == "POSI 2");
    CHECK(has_issue(log, 470, "not a number: 'abc'"));
    CHECK(log.stream("gyro")->bad_rows == 1);
    bool ignored_noted = false;
    for (const auto& n : log.notes) ignored_noted = ignored_noted || n == "lines ignored: AHRS 4, WIFI 1";
    CHECK(ignored_noted);
    // merged_records interleaves the streams in time order.
    const auto records = merged_records(log);
    CHECK(records.size() == 199 + 40 + 20 + 1);
    for (size_t i = 1; i < records.size(); ++i) REQUIRE(records[i - 1]->t_ns <= records[i]->t_ns);
}

TEST_CASE("column map: names and indices, units, axis remap, strict keys") {
    const std::string dir = temp_dir();
    std::ostringstream f;
    f << "ms;gyr_x;gyr_y;gyr_z;acc_x;acc_y;acc_z;baro\n";
    for (int i = 0; i < 100; ++i) f << i * 10 << ";" << 57.29577951308232 << ";0;0;0.1;0;1.0;1013.0\n";
    const std::string path = write_file(dir, "custom.csv", f.str());
    const nlohmann::json map = {
        {"time", {{"column", "ms"}, {"unit", "ms"}}},
        {"accel", {{"columns", {"acc_x", "acc_y", "acc_z"}}, {"unit", "g"}}},
        {"gyro", {{"columns", {1, 2, 3}}, {"unit", "deg/s"}}},
        {"pressure", {{"column", "baro"}, {"unit", "hPa"}}},
        {"axes", "x=-y, y=x, z=z"},
    };
    ReadOptions options;
    options.column_map = &map;
    const SensorLog log = read_sensor_file(path, options);
    CHECK(log.format == "column-map");
    REQUIRE(log.imu.size() == 100);
    CHECK(log.imu[1].header.t_ns == 10000000);
    // body x = -sensor y, body y = sensor x.
    CHECK(log.imu[0].gyro_radps[0] == doctest::Approx(0.0));
    CHECK(log.imu[0].gyro_radps[1] == doctest::Approx(1.0));
    CHECK(log.imu[0].accel_mps2[1] == doctest::Approx(0.980665));
    CHECK(log.imu[0].accel_mps2[2] == doctest::Approx(9.80665));
    CHECK(log.baro[0].pressure_pa == doctest::Approx(101300.0));
    CHECK(log.stream("accel")->rate_hz == doctest::Approx(100.0));

    // A quaternion: 90 degrees about z, the same remap as "x=-y, y=x".
    nlohmann::json rotated = map;
    rotated.erase("axes");
    rotated["rotation_q_body_from_sensor"] = {std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};
    options.column_map = &rotated;
    const SensorLog log_q = read_sensor_file(path, options);
    CHECK(log_q.imu[0].gyro_radps[1] == doctest::Approx(1.0));
    CHECK(log_q.imu[0].accel_mps2[1] == doctest::Approx(0.980665));

    nlohmann::json bad = map;
    bad["accel"]["colums"] = {"a", "b", "c"};
    options.column_map = &bad;
    try {
        read_sensor_file(path, options);
        FAIL("no exception");
    } catch (const ReadError& e) {
        CHECK(std::string(e.what()).find("column map /accel/colums: unknown key") != std::string::npos);
    }
    nlohmann::json missing = map;
    missing["gyro"]["columns"] = {"gx", "gy", "gz"};
    options.column_map = &missing;
    CHECK_THROWS_WITH_AS(read_sensor_file(path, options),
                         doctest::Contains("column map /gyro/columns/0: no column named 'gx'"), ReadError);
    // Without a map the file is not recognised.
    CHECK_THROWS_WITH_AS(read_sensor_file(path), doctest::Contains("unknown format"), ReadError);
}

TEST_CASE("format names and forced formats") {
    const auto names = supported_formats();
    for (const char* n : {"pednav-csv", "xio-ngimu-csv", "microstrain-sensorconnect-a",
                          "microstrain-sensorconnect-b", "xsens-mtw-tsv", "xsens-mtmanager-csv",
                          "xsens-converted-g-csv", "humolire-senslogs", "ipin-logfile", "column-map"}) {
        CHECK(std::find(names.begin(), names.end(), n) != names.end());
    }
    const std::string dir = temp_dir();
    const std::string path =
        write_file(dir, "x.csv", "t,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n0.01,0,0,9.8,0,0,0\n");
    ReadOptions options;
    options.format = "xio-ngimu-csv";
    CHECK_THROWS_AS(read_sensor_file(path, options), ReadError);
    options.format = "no-such-format";
    CHECK_THROWS_WITH_AS(read_sensor_file(path, options), doctest::Contains("unknown format name"),
                         ReadError);
    CHECK(detect_format(path) == "pednav-csv");
}

TEST_CASE("canonical CSV: separate rows of different streams at the same time are all kept") {
    const std::string dir = temp_dir();
    const std::string text =
        "t,ax,ay,az,gx,gy,gz,mx,my,mz\n"
        "0.00,0,0,9.8,0,0,0,,,\n"
        "0.00,,,,,,,20,0,-40\n"
        "0.01,0,0,9.8,0,0,0,,,\n"
        "0.01,0,0,9.8,0,0,0,,,\n";  // a real duplicate of the IMU stream
    const SensorLog log = read_sensor_file(write_file(dir, "sparse.csv", text));
    CHECK(log.imu.size() == 2);
    CHECK(log.mag.size() == 1);
    CHECK(has_issue(log, 5, "1 samples with a repeated timestamp dropped in accel/gyro"));
    const auto records = merged_records(log);
    REQUIRE(records.size() == 3);
    CHECK(records[0]->type == PN_REC_IMU);
    CHECK(records[1]->type == PN_REC_MAG);
}

TEST_CASE("MicroStrain layout B: a row flagged invalid is skipped") {
    const std::string dir = temp_dir();
    const std::string d = "inertial-1.2:";
    std::string header = "Time";
    for (const char* c : {"estCompensatedAccelX", "estCompensatedAccelY", "estCompensatedAccelZ",
                          "estAngularRateX", "estAngularRateY", "estAngularRateZ"}) {
        header.append(",").append(d).append(c).append(",").append(d).append(c).append(":valid");
    }
    std::string text = header + "\n";
    text += "0,1,1,2,1,-9.8,1,0.1,1,0.2,1,0.3,1\n";
    text += "0.004,1,1,2,1,-9.8,1,0.1,0,0.2,1,0.3,1\n";  // gyro x not valid
    text += "0.008,1,1,2,1,-9.8,1,0.1,1,0.2,1,0.3,1\n";
    const SensorLog log = read_sensor_file(write_file(dir, "ms.csv", text));
    CHECK(log.format == "microstrain-sensorconnect-b");
    REQUIRE(log.imu.size() == 2);
    CHECK(has_issue(log, 3, "flagged invalid by the sensor (inertial-1.2:estAngularRateX:valid)"));
    // Forward-right-down to forward-left-up: (x, -y, -z).
    CHECK(log.imu[0].accel_mps2[0] == doctest::Approx(1.0));
    CHECK(log.imu[0].accel_mps2[1] == doctest::Approx(-2.0));
    CHECK(log.imu[0].accel_mps2[2] == doctest::Approx(9.8));
    CHECK(log.imu[0].gyro_radps[2] == doctest::Approx(-0.3));
}

TEST_CASE("Xsens: PacketCounter / rate, unwrapped at 65536; a 10 s gap is reported") {
    const std::string dir = temp_dir();
    std::string text =
        "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\n";
    for (int c : {65533, 65534, 65535, 0, 1, 1001}) {
        text += std::to_string(c) + ".0\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\n";
    }
    const SensorLog log = read_sensor_file(write_file(dir, "wrap.txt", text));
    CHECK(log.format == "xsens-mtw-tsv");
    REQUIRE(log.imu.size() == 6);
    CHECK(log.imu[0].header.t_ns == 655330000000LL);
    CHECK(log.imu[3].header.t_ns == 655360000000LL);
    CHECK(log.imu[5].header.t_ns == 665370000000LL);
    CHECK(has_issue(log, 8, "gap of 10.000 s in accel/gyro"));
    CHECK(log.stream("accel")->gaps == 1);
}

TEST_CASE("Xsens: a pressure column filled on every 10th row; the other rows keep their IMU sample") {
    // The empty pressure cell is the last of a tab-separated row: a field
    // of its own, not a truncated row.
    const std::string dir = temp_dir();
    std::string text =
        "Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tPressure\n";
    for (int c = 0; c < 100; ++c)
        text += std::to_string(c) + "\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\t" + (c % 10 == 0 ? "101325" : "") + "\n";
    const SensorLog log = read_sensor_file(write_file(dir, "sparse_pressure.txt", text));
    CHECK(log.format == "xsens-mtw-tsv");
    CHECK(log.imu.size() == 100);
    REQUIRE(log.baro.size() == 10);
    CHECK(log.baro[1].pressure_pa == doctest::Approx(101325.0));
    CHECK(log.issues.empty());
}

TEST_CASE("Xsens: a tab at the end of every row, with or without one after the header") {
    const std::string dir = temp_dir();
    for (const char* header_end : {"\t\n", "\n"}) {
        std::string text = std::string("Acquisition frequency: 100 Hz\nPacketCounter\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z") +
                           header_end;
        for (int c = 0; c < 100; ++c) text += std::to_string(c) + "\t0.1\t0.2\t9.8\t0.01\t0.02\t0.03\t\n";
        const SensorLog log = read_sensor_file(write_file(dir, "trailing_tab.txt", text));
        CAPTURE(header_end);
        CHECK(log.format == "xsens-mtw-tsv");
        CHECK(log.imu.size() == 100);
        CHECK(log.issues.empty());
    }
}

TEST_CASE("x-io CSV: deg/s and g converted, a repeated row dropped") {
    const std::string dir = temp_dir();
    const std::string text =
        "Time (s),Gyroscope X (deg/s),Gyroscope Y (deg/s),Gyroscope Z (deg/s),Accelerometer X (g),"
        "Accelerometer Y (g),Accelerometer Z (g)\n"
        "0,180,0,0,0,0,1\n"
        "0.0025,180,0,0,0,0,1\n"
        "0.0025,180,0,0,0,0,1\n"
        "0.005,90,0,0,0,0.5,1\n";
    const SensorLog log = read_sensor_file(write_file(dir, "xio.csv", text));
    CHECK(log.format == "xio-ngimu-csv");
    REQUIRE(log.imu.size() == 3);
    CHECK(log.imu[0].gyro_radps[0] == doctest::Approx(M_PI));
    CHECK(log.imu[2].gyro_radps[0] == doctest::Approx(M_PI / 2));
    CHECK(log.imu[2].accel_mps2[1] == doctest::Approx(0.5 * 9.80665));
    CHECK(has_issue(log, 4, "1 samples with a repeated timestamp dropped"));
}
