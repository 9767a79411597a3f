// SPDX-License-Identifier: Apache-2.0
// RecordStream: a file pulled a block at a time gives exactly the records,
// issues, notes and streams of the whole-file read, bad rows in a long file
// keep the rows around them, and the summaries of a file too long to hold stay
// exact (samples spilled to a temporary file, medians by radix selection).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <sstream>

#include <nlohmann/json.hpp>

#include "pednav_io/record_stream.hpp"
#include "pednav_io/writers.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

int64_t seconds_to_ns_for_test(double t_s) { return static_cast<int64_t>(std::llround(t_s * 1e9)); }

// Every record of `path`, pulled `block` at a time.
std::vector<InputRecord> pull(RecordStream& stream, size_t block) {
    std::vector<InputRecord> all, part;
    while (stream.read(part, block) > 0) {
        REQUIRE(part.size() <= block);
        all.insert(all.end(), part.begin(), part.end());
        part.clear();
    }
    CHECK(stream.done());
    return all;
}

// The records of merged_records(log) and `streamed` are the same bytes, in the same order.
void check_same_records(const SensorLog& log, const std::vector<InputRecord>& streamed) {
    const auto whole = merged_records(log);
    REQUIRE(streamed.size() == whole.size());
    size_t differing = 0;
    for (size_t i = 0; i < whole.size(); ++i) {
        if (streamed[i].header.struct_size != whole[i]->struct_size ||
            std::memcmp(&streamed[i], whole[i], whole[i]->struct_size) != 0)
            ++differing;
    }
    CHECK(differing == 0);
}

// The JSON of `pednav inspect --json` without the records.
std::string described(const SensorLog& log) { return sensor_log_json(log).dump(); }

void check_stream_matches_whole_read(const std::string& path, const ReadOptions& options = {}) {
    CAPTURE(path);
    const SensorLog whole = read_sensor_file(path, options);
    for (size_t block : {size_t{7}, size_t{4096}}) {
        RecordStream stream(path, options);
        const std::vector<InputRecord> records = pull(stream, block);
        check_same_records(whole, records);
        CHECK(stream.log().records.imu == whole.imu.size());
        CHECK(described(stream.log()) == described(whole));
    }
}

// A canonical CSV of a still IMU at 400 Hz with a magnetometer at 100 Hz and a
// barometer at 25 Hz on rows of their own (empty cells elsewhere), `rows` IMU
// rows, a NaN at IMU row `bad` (when > 0).
std::string sparse_csv(size_t rows, size_t bad) {
    std::ostringstream f;
    f << "t,ax,ay,az,gx,gy,gz,mx,my,mz,p\n";
    char line[200];
    for (size_t i = 0; i < rows; ++i) {
        const double t = static_cast<double>(i) * 0.0025;
        const double r = 0.01 * std::sin(0.7 * static_cast<double>(i));
        if (i == bad) {
            std::snprintf(line, sizeof line, "%.4f,0.05,-0.03,nan,0.001,-0.002,0.0005,,,,\n", t);
        } else {
            std::snprintf(line, sizeof line, "%.4f,%.5f,%.5f,%.5f,%.6f,-0.002,0.0005,,,,\n", t, 0.05 + r,
                          -0.03 - r, 9.81 + r, 0.001 + r / 10);
        }
        f << line;
        if (i % 4 == 0) {
            std::snprintf(line, sizeof line, "%.4f,,,,,,,%.3f,-4.2,-41.7,\n", t + 0.001, 20.1 + r);
            f << line;
        }
        if (i % 16 == 0) {
            std::snprintf(line, sizeof line, "%.4f,,,,,,,,,,%.2f\n", t + 0.002, 101325.0 + 10 * r);
            f << line;
        }
    }
    return f.str();
}

}  // namespace

TEST_CASE("a sparse canonical CSV pulled in blocks gives the records and warnings of the whole-file read") {
    const std::string dir = temp_dir();
    // Three streams on rows of their own, a NaN, time going back, a repeated time and a 2 s gap.
    std::string text = sparse_csv(4000, 1000);                    // IMU rows up to t = 9.9975 s
    text += "11.9975,0.05,-0.03,9.81,0.001,-0.002,0.0005,,,,\n";  // 2 s after the last: a gap
    text += "11.5,0.05,-0.03,9.81,0.001,-0.002,0.0005,,,,\n";     // backwards
    text += "11.9975,0.05,-0.03,9.81,0.001,-0.002,0.0005,,,,\n";  // repeated
    text += "12.0,0.05,-0.03,9.81,0.001,-0.002,0.0005,,,,\n";
    const std::string path = write_file(dir, "sparse.csv", text);
    const SensorLog whole = read_sensor_file(path);
    // 4000 rows + 2 after the gap, less the NaN; 1000 magnetometer rows; 250 barometer rows.
    CHECK(whole.imu.size() == 4001);
    CHECK(whole.mag.size() == 1000);
    CHECK(whole.baro.size() == 250);
    // The NaN is IMU row 1000: 250 magnetometer and 63 barometer rows before it.
    CHECK(has_issue(whole, 1002 + 250 + 63, "row skipped: non-finite value 'nan' in column az"));
    CHECK(has_issue(whole, 5252 + 1,
                    "row skipped: time goes backwards (11.5 s after 11.9975 s) in accel/gyro"));
    CHECK(has_issue(whole, 5252 + 2, "1 samples with a repeated timestamp dropped in accel/gyro"));
    CHECK(has_issue(whole, 5252, "gap of 2.000 s in accel/gyro"));
    check_stream_matches_whole_read(path);
}

TEST_CASE("the shared recordings stream as they are read whole: x-io, MicroStrain, Xsens, senslogs pair") {
    const std::string d = data_dir();
    for (const std::string file :
         {"/xio-gait-ngimu/short_walk.csv", "/koroglu-foot-gcp/SensorConnectData_35.csv",
          "/ipol-gait-waist-feet/1-1_lb.txt", "/humolire-phone/user1_straight"}) {
        if (!exists(d + file)) {
            MESSAGE("skipped, not found: " << d + file);
            continue;
        }
        check_stream_matches_whole_read(d + file);
    }
}

TEST_CASE(
    "a bad row in the middle of a long file keeps the rows before and after it; its summaries stay exact") {
    // 120 000 rows at 100 Hz with a jitter of up to 1 ms: more samples than the
    // reader keeps in memory, every interval a different number.
    const std::string dir = temp_dir();
    const size_t rows = 120000, bad = 60000;
    std::ostringstream f;
    f << "t,ax,ay,az,gx,gy,gz\n";
    std::vector<double> times;
    char line[160];
    for (size_t i = 0; i < rows; ++i) {
        const double t = static_cast<double>(i) * 0.01 + static_cast<double>((i * 7919) % 1000) * 1e-6;
        if (i == bad) {
            std::snprintf(line, sizeof line, "%.6f,0.05,-0.03,9.81,abc,-0.002,0.0005\n", t);
        } else {
            std::snprintf(line, sizeof line, "%.6f,0.05,-0.03,9.81,0.001,-0.002,0.0005\n", t);
            times.push_back(std::stod(std::string(line, std::strchr(line, ',') - line)));
        }
        f << line;
    }
    const std::string path = write_file(dir, "long.csv", f.str());
    RecordStream stream(path);
    const std::vector<InputRecord> records = pull(stream, 1000);
    const SensorLog& log = stream.log();
    REQUIRE(records.size() == rows - 1);
    CHECK(has_issue(log, bad + 2, "row skipped: not a number: 'abc' in column gx"));
    // The rows on either side of the bad one, and the last.
    CHECK(records[bad - 1].header.t_ns == seconds_to_ns_for_test(times[bad - 1]));
    CHECK(records[bad].header.t_ns == seconds_to_ns_for_test(times[bad]));
    CHECK(records.back().header.t_ns == seconds_to_ns_for_test(times.back()));
    // The median interval, found in the test with nth_element over all of them.
    std::vector<double> dt;
    for (size_t i = 1; i < times.size(); ++i) dt.push_back(times[i] - times[i - 1]);
    std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
    const StreamInfo* accel = log.stream("accel");
    REQUIRE(accel != nullptr);
    CHECK(accel->count == rows - 1);
    CHECK(accel->bad_rows == 1);
    CHECK(accel->median_rate_hz == 1.0 / dt[dt.size() / 2]);
    CHECK(accel->gaps == 0);
    CHECK(log.issues.size() == 1);
}

TEST_CASE("a stream further behind the others than the merge window loses the rows that cannot be placed") {
    // IMU rows at 100 Hz for 10 s; the magnetometer gives one row at t = 0, then
    // ten rows from t = 5 s only after the last IMU row.
    const std::string dir = temp_dir();
    std::ostringstream f;
    f << "t,ax,ay,az,gx,gy,gz,mx,my,mz\n";
    char line[160];
    for (int i = 0; i < 1000; ++i) {
        std::snprintf(line, sizeof line, "%.2f,0.05,-0.03,9.81,0.001,-0.002,0.0005,,,\n", i * 0.01);
        f << line;
        if (i == 0) f << "0.00,,,,,,,20,-4,-41\n";
    }
    for (int k = 0; k < 10; ++k) {
        std::snprintf(line, sizeof line, "%.2f,,,,,,,20,-4,-41\n", 5.0 + k * 0.01);
        f << line;
    }
    const std::string path = write_file(dir, "late_mag.csv", f.str());
    // Read whole (and with no window): sorted into place.
    CHECK(read_sensor_file(path).mag.size() == 11);
    RecordStream unbounded(path, {}, 0);
    CHECK(pull(unbounded, 512).size() == 1011);
    // A window of 100 records: the IMU goes on without the magnetometer; its
    // late rows (lines 1003-1012) are reported and skipped.
    RecordStream windowed(path, {}, 100);
    const std::vector<InputRecord> records = pull(windowed, 512);
    CHECK(records.size() == 1001);
    CHECK(windowed.log().records.mag == 1);
    CHECK(windowed.log().stream("mag")->bad_rows == 10);
    CHECK(has_issue(windowed.log(), 1003,
                    "row skipped: mag sample at t=5 s is earlier than samples of the other "
                    "streams already passed on"));
    CHECK(has_issue(windowed.log(), 1012, "mag sample at t=5.09 s"));
    int64_t last = INT64_MIN;
    for (const auto& r : records) {
        CHECK(r.header.t_ns >= last);
        last = r.header.t_ns;
    }
}

TEST_CASE("the first IMU time is known before the records are read, and they still all come") {
    const std::string dir = temp_dir();
    const std::string path = write_file(
        dir, "first.csv", "t,ax,ay,az,gx,gy,gz\n# a comment\n2.5,0,0,9.8,0,0,0\n2.6,0,0,9.8,0,0,0\n");
    RecordStream stream(path);
    int64_t t0 = 0;
    REQUIRE(stream.first_imu_t_ns(&t0));
    CHECK(t0 == 2500000000);
    CHECK(pull(stream, 1).size() == 2);
}

TEST_CASE("a NUL byte past the first 64 KiB ends the file there: the records before it come, then the error") {
    const std::string dir = temp_dir();
    std::ostringstream f;
    f << "t,ax,ay,az,gx,gy,gz\n";
    char line[160];
    for (int i = 0; i < 9000; ++i) {
        std::snprintf(line, sizeof line, "%.2f,0.05,-0.03,9.81,0.001,-0.002,0.0005\n", i * 0.01);
        f << line;
        if (i == 7000) f << std::string(1, '\0');
    }
    const std::string text = f.str();
    const std::string path = write_file(dir, "nul.csv", text);
    const std::string offset = std::to_string(text.find('\0'));
    RecordStream stream(path);
    std::vector<InputRecord> part;
    size_t got = 0;
    std::string error;
    try {
        while (stream.read(part, 1000) > 0) got += part.size(), part.clear();
    } catch (const ReadError& e) {
        error = e.what();
    }
    CHECK(error == path + ": binary file (a NUL byte at offset " + offset + "), not a text recording");
    // Every row before the NUL's line: rows 0 to 7 000.
    CHECK(got == 7001);
    CHECK(stream.done());
    CHECK_THROWS_WITH(read_sensor_file(path), error.c_str());
}

TEST_CASE("a CR LF split by the end of the first 64 KiB chunk ends one line, not two") {
    const std::string dir = temp_dir();
    std::string text = "t,ax,ay,az,gx,gy,gz\r\n";
    size_t lines = 1, i = 0;
    char row[96];
    auto add_row = [&](const char* az) {
        std::snprintf(row, sizeof row, "%zu.000,0.05,-0.03,%s,0.001,-0.002,0.0005\r\n", i++, az);
        text += row;
        ++lines;
    };
    while (text.size() < 65536 - 200) add_row("9.81");
    // A comment long enough that the next row's CR is the chunk's last byte, its LF the next chunk's first.
    std::snprintf(row, sizeof row, "%zu.000,0.05,-0.03,9.81,0.001,-0.002,0.0005\r\n", i);
    const size_t row_bytes = std::strlen(row);
    text += "#" + std::string(65536 - (row_bytes - 1) - text.size() - 3, '-') + "\r\n";
    ++lines;
    add_row("9.81");
    REQUIRE(text.size() == 65537);
    REQUIRE(text[65535] == '\r');
    for (int k = 0; k < 100; ++k) add_row("9.81");
    add_row("nan");  // named by its line
    const size_t nan_line = lines;
    for (int k = 0; k < 100; ++k) add_row("9.81");
    const std::string path = write_file(dir, "crlf.csv", text);
    RecordStream stream(path);
    const size_t records = pull(stream, 4096).size();
    CHECK(records == i - 1);
    CHECK(stream.log().issues.size() == 1);
    CHECK(has_issue(stream.log(), nan_line, "row skipped: non-finite value 'nan' in column az"));
}
