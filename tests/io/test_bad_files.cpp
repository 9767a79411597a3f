// SPDX-License-Identifier: Apache-2.0
// Bad files: each problem is reported with its line number and the good rows
// around it are kept; fatal ones throw ReadError naming the file and reason.
#include <doctest/doctest.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "pednav_io/sensor_log.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

// Canonical CSV at 100 Hz; rows i = 0..n-1 at t = t0 + i / 100; line numbers
// are 1 (comment) + 1 (header) + i + 1.
std::string canonical_rows(int n, double t0 = 0.0) {
    std::ostringstream out;
    out.precision(10);
    for (int i = 0; i < n; ++i) {
        out << t0 + i * 0.01 << ",0.1,0.2,9.8," << 0.01 * i << ",0,0.02\n";
    }
    return out.str();
}

const std::string kHeader = "# a walk\nt,ax,ay,az,gx,gy,gz\n";

std::string error_of(const std::string& path) {
    try {
        read_sensor_file(path);
    } catch (const ReadError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("canonical CSV: a clean file") {
    const std::string dir = temp_dir();
    const std::string path = write_file(dir, "clean.csv", kHeader + canonical_rows(300));
    const SensorLog log = read_sensor_file(path);
    CHECK(log.format == "pednav-csv");
    CHECK(log.imu.size() == 300);
    CHECK(log.issues.empty());
    CHECK(log.imu[7].header.t_ns == 70000000);
    CHECK(log.imu[7].gyro_radps[0] == doctest::Approx(0.07));
    CHECK(log.stream("accel")->rate_hz == doctest::Approx(100.0));
}

TEST_CASE("canonical CSV: truncated line, text, NaN, backwards time, duplicate, 10 s gap") {
    const std::string dir = temp_dir();
    std::string body = canonical_rows(100);  // lines 3..102
    body += "1.00,0.1,0.2\n";                // line 103: truncated
    body += "1.01,0.1,abc,9.8,0,0,0\n";      // line 104: text in a number
    body += "1.02,0.1,0.2,NaN,0,0,0\n";      // line 105: NaN
    body += "1.03,0.1,0.2,9.8,0,0,0\n";      // line 106: good
    body += "0.50,0.1,0.2,9.8,0,0,0\n";      // line 107: time goes backwards
    body += "1.03,0.1,0.2,9.8,0,0,0\n";      // line 108: repeated time
    body += canonical_rows(100, 11.04);      // lines 109..208: after a 10 s gap
    body += "12.05,0.1,0.2,9.";              // line 209: cut off while writing
    const std::string path = write_file(dir, "bad_rows.csv", kHeader + body);
    const SensorLog log = read_sensor_file(path);
    CHECK(log.imu.size() == 100 + 1 + 100);
    CHECK(has_issue(log, 103, "truncated row"));
    CHECK(has_issue(log, 104, "not a number: 'abc' in column ay"));
    CHECK(has_issue(log, 105, "non-finite value 'NaN' in column az"));
    CHECK(has_issue(log, 107, "time goes backwards"));
    CHECK(has_issue(log, 108, "1 samples with a repeated timestamp dropped"));
    CHECK(has_issue(log, 109, "gap of 10.010 s"));
    CHECK(has_issue(log, 209, "truncated row"));
    const StreamInfo* accel = log.stream("accel");
    REQUIRE(accel != nullptr);
    CHECK(accel->bad_rows == 5);
    CHECK(accel->gaps == 1);
    CHECK(accel->duration_s == doctest::Approx(12.03));
    // Good rows on both sides are kept, in order.
    CHECK(log.imu[99].header.t_ns == 990000000);
    CHECK(log.imu[100].header.t_ns == 1030000000);
    CHECK(log.imu[101].header.t_ns == 11040000000);
}

TEST_CASE("issues beyond the listing cap are counted, not listed") {
    const std::string dir = temp_dir();
    std::ostringstream body;
    body.precision(10);
    for (int i = 0; i < 600; ++i)  // every odd row bad: 300 issues
        body << i * 0.01 << ",0.1,0.2," << (i % 2 ? "nan" : "9.8") << ",0,0,0\n";
    const std::string path = write_file(dir, "many_bad_rows.csv", kHeader + body.str());
    ReadOptions options;
    const SensorLog log = read_sensor_file(path, options);
    CHECK(log.imu.size() == 300);
    CHECK(log.issues.size() == options.max_issues);
    CHECK(log.issues_not_listed == 300 - options.max_issues);
    for (const auto& issue : log.issues) CHECK(issue.message.find("non-finite value 'nan'") != std::string::npos);
    CHECK(log.stream("accel")->bad_rows == 300);
}

TEST_CASE("canonical CSV: optional streams, empty cells, extra columns") {
    const std::string dir = temp_dir();
    const std::string text =
        "t,ax,ay,az,gx,gy,gz,mx,my,mz,p,comment\n"
        "0.00,0,0,9.8,0,0,0,20,0,-40,101325,a\n"
        "0.01,0,0,9.8,0,0,0,,,,,b\n"
        "0.02,,,,,,,21,0,-40,,c\n"
        "0.03,0,0,9.8,0,0,0,,,,101320,d\n";
    const SensorLog log = read_sensor_file(write_file(dir, "multi.csv", text));
    CHECK(log.imu.size() == 3);
    CHECK(log.mag.size() == 2);
    CHECK(log.baro.size() == 2);
    CHECK(log.mag[1].header.t_ns == 20000000);
    CHECK(log.mag[1].mag_ut[0] == doctest::Approx(21.0));
    CHECK(log.baro[1].pressure_pa == doctest::Approx(101320.0));
    CHECK(log.issues.empty());
}

TEST_CASE("unit sanity: gravity ~1 and gyro in deg/s are reported, not converted") {
    const std::string dir = temp_dir();
    std::ostringstream body;
    for (int i = 0; i < 200; ++i)
        body << i * 0.01 << ",0.01,0.02,1.0," << (i % 20 == 0 ? 300 : 5) << ",0,0\n";
    const SensorLog log =
        read_sensor_file(write_file(dir, "units.csv", "t,ax,ay,az,gx,gy,gz\n" + body.str()));
    CHECK(has_issue(log, 0, "look like g, not m/s^2"));
    CHECK(has_issue(log, 0, "look like deg/s"));
    CHECK(log.imu[0].accel_mps2[2] == doctest::Approx(1.0));  // not converted
}

TEST_CASE("fatal: missing, empty, binary, unknown, no accelerometer/gyroscope columns") {
    const std::string dir = temp_dir();
    CHECK(error_of(dir + "/nope.csv").find("nope.csv: file not found") != std::string::npos);
    CHECK(error_of(write_file(dir, "empty.csv", "")).find("the file is empty") != std::string::npos);
    CHECK(error_of(write_file(dir, "blank.csv", "\n\n  \n")).find("empty") != std::string::npos);
    CHECK(error_of(write_file(dir, "binary.csv", std::string("PK\x03\x04\x00\x00\x01\x02", 8) + "abc"))
              .find("binary file") != std::string::npos);
    CHECK(error_of(write_file(dir, "unknown.csv", "foo,bar\n1,2\n")).find("unknown format") !=
          std::string::npos);
    const std::string no_gyro = error_of(write_file(dir, "nogyro.csv", "# x\nt,ax,ay,az\n0,0,0,9.8\n"));
    CHECK(no_gyro.find("nogyro.csv:2: no accelerometer/gyroscope columns: the header lacks gx, gy, gz") !=
          std::string::npos);
    const std::string only_bad =
        error_of(write_file(dir, "allbad.csv", "t,ax,ay,az,gx,gy,gz\n0,x,0,0,0,0,0\n"));
    CHECK(only_bad.find(
              "no accelerometer and gyroscope sample could be read (first problem: line 2: row skipped: "
              "not a number: 'x' in column ax)") != std::string::npos);
    CHECK(error_of(write_file(dir, "utf16.csv", std::string("\xff\xfet\0,\0", 6))).find("UTF-16") !=
          std::string::npos);
    // A UTF-8 byte order mark (Windows exports) is skipped.
    const SensorLog bom =
        read_sensor_file(write_file(dir, "bom.csv", "\xef\xbb\xbft,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n"));
    CHECK(bom.format == "pednav-csv");
    CHECK(bom.imu.size() == 1);
    try {
        read_sensor_file(dir + "/nope.csv");
        FAIL("no exception");
    } catch (const ReadError& e) {
        CHECK(e.path() == dir + "/nope.csv");
        CHECK(e.line() == 0);
    }
}

TEST_CASE("regression (issue 18): a forced format on a file it does not fit fails cleanly") {
    const std::string dir = temp_dir();
    const std::string comment = write_file(dir, "comment.csv", "# one comment line\n");
    for (const char* format : {"pednav-csv", "xio-ngimu-csv", "microstrain-sensorconnect-a",
                               "microstrain-sensorconnect-b"}) {
        ReadOptions options;
        options.format = format;
        try {
            read_sensor_file(comment, options);
            FAIL("no exception for ", format);
        } catch (const ReadError& e) {
            CHECK(e.line() == 0);  // there is no line 2 to name
            CHECK(e.reason().find("no header line for format") != std::string::npos);
        }
    }
    ReadOptions options;
    options.format = "pednav-csv";
    const std::string no_t = write_file(dir, "no_t.csv", "x,ax,ay,az,gx,gy,gz\n0,0,0,9.8,0,0,0\n");
    try {
        read_sensor_file(no_t, options);
        FAIL("no exception");
    } catch (const ReadError& e) {
        CHECK(e.line() == 1);
        CHECK(e.reason() == "no time column: the header lacks t");
    }
}

TEST_CASE("regression (issue 18): Unix times in t, a time beyond the clock, CR-only lines") {
    const std::string dir = temp_dir();
    std::ostringstream ns;
    ns.precision(20);
    for (int i = 0; i < 100; ++i) ns << 1700000000000000000LL + i * 10000000LL << ",0,0,9.8,0,0,0\n";
    const SensorLog unix_ns = read_sensor_file(write_file(dir, "ns.csv", "t,ax,ay,az,gx,gy,gz\n" + ns.str()));
    REQUIRE(unix_ns.imu.size() == 100);
    // Seconds near 1.7e9 hold ~0.24 us: the nanoseconds come back within a microsecond.
    CHECK(std::llabs(unix_ns.imu[0].header.t_ns - 1700000000000000000LL) < 1000);
    CHECK(std::llabs(unix_ns.imu[1].header.t_ns - unix_ns.imu[0].header.t_ns - 10000000) < 1000);
    CHECK(has_issue(unix_ns, 2, "is a Unix time in nanoseconds"));

    // One absurd time among times in seconds: that row is skipped, not the clock overflowed.
    const SensorLog one =
        read_sensor_file(write_file(dir, "one.csv", "t,ax,ay,az,gx,gy,gz\n" + canonical_rows(3) +
                                                         "1e12,0,0,9.8,0,0,0\n" + canonical_rows(3, 0.05)));
    CHECK(one.imu.size() == 6);
    CHECK(has_issue(one, 5, "is beyond the +-9.2e+09 s a nanosecond clock holds"));
    for (const auto& r : one.imu) CHECK(r.header.t_ns < 1000000000);

    std::string cr = "t,ax,ay,az,gx,gy,gz\n" + canonical_rows(50);
    for (auto& c : cr)
        if (c == '\n') c = '\r';
    const SensorLog mac = read_sensor_file(write_file(dir, "cr.csv", cr));
    CHECK(mac.imu.size() == 50);
    CHECK(mac.issues.empty());
}

TEST_CASE("regression (issue 18): a quiet, quantised IMU at rest is not called saturated") {
    // Values on a coarse grid, the gravity axis repeating its maximum: below the 2 g / 2 rad/s floors.
    const std::string dir = temp_dir();
    std::ostringstream body;
    for (int i = 0; i < 1000; ++i)
        body << i * 0.01 << ",0," << (i % 3 == 0 ? 0.01 : 0.0) << "," << (i % 2 ? 9.81 : 9.80) << ","
             << (i % 4 == 0 ? 0.002 : 0.0) << ",0,0\n";
    const SensorLog log = read_sensor_file(write_file(dir, "quiet.csv", "t,ax,ay,az,gx,gy,gz\n" + body.str()));
    CHECK(log.imu.size() == 1000);
    CHECK(log.issues.empty());
}

TEST_CASE("regression (issue 18, fuzz findings 1-3): forced readers on the crashing inputs throw ReadError") {
    // libFuzzer inputs (fuzz-ci): past the lines in header_of, fields[-1] in parse_scalar.
    const std::string dir = std::string(PEDNAV_IO_TEST_DATA_DIR) + "/fuzz/";
    const struct {
        const char* file;
        const char* format;
        const char* reason;
    } cases[] = {
        {"read_microstrain_sensorconnect_a-08e8061a.txt", "microstrain-sensorconnect-a", "no header line for format"},
        {"read_microstrain_sensorconnect_a-df209a7f.txt", "microstrain-sensorconnect-a", "no header line for format"},
        {"read_microstrain_sensorconnect_b-5361e7c1.txt", "microstrain-sensorconnect-b", "no time column in the header"},
        {"read_microstrain_sensorconnect_b-e3ee0c26.txt", "microstrain-sensorconnect-b", "no time column in the header"},
        {"read_pednav_csv-35983d57.txt", "pednav-csv", "no time column: the header lacks t"},
    };
    for (const auto& c : cases) {
        ReadOptions options;
        options.format = c.format;
        INFO(c.file);
        REQUIRE(exists(dir + c.file));
        try {
            read_sensor_file(dir + c.file, options);
            FAIL("no exception");
        } catch (const ReadError& e) {
            CHECK(e.reason().find(c.reason) != std::string::npos);
        }
    }
}
