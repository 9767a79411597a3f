// SPDX-License-Identifier: Apache-2.0
// Internal: what every reader shares. A reader parses its layout and hands
// samples, already in SI units and body axes, to a LogBuilder, which checks time
// order, drops duplicates, counts bad rows and gaps, pairs separate accelerometer
// and gyroscope streams, checks unit sanity and fills SensorLog::streams.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io::detail {

enum StreamId {
    stream_accel = 0,
    stream_gyro,
    stream_mag,
    stream_pressure,
    stream_gnss,
    stream_truth,
    stream_count
};
constexpr unsigned stream_bit(StreamId s) { return 1u << static_cast<unsigned>(s); }
constexpr unsigned kImuBits = stream_bit(stream_accel) | stream_bit(stream_gyro);
const char* stream_name(StreamId s);

// Time order of one clock: the row clock of a one-table file, or the own clock
// of one stream in a multi-stream file.
struct Clock {
    explicit Clock(std::string clock_name) : name(std::move(clock_name)) {}
    std::string name;
    bool has_last = false;
    int64_t last_t_ns = 0;
};

// Times in a log are int64 nanoseconds: |t| below this many seconds (~292 years).
constexpr double kMaxTimeS = 9.2e9;
int64_t seconds_to_ns(double t_s);

class LogBuilder {
public:
    LogBuilder(SensorLog& log, const ReadOptions& options);

    void note(const std::string& text);
    // Prefix for issue messages while reading one file of a multi-file recording.
    void set_context(const std::string& context) { context_ = context; }
    void issue(size_t line, const std::string& message);
    // The row (or sample) is skipped; counted as a bad row of every stream in
    // `streams`. The issue reads "<unit> skipped: <message>".
    void bad_row(size_t line, const std::string& message, unsigned streams, const char* unit = "row");
    // True when a row/sample at t_s is to be kept: going backwards is a bad row,
    // a repeated time is dropped and counted (one summary issue at finish).
    bool accept_time(Clock& clock, size_t line, double t_s, unsigned streams);

    void add_imu(size_t line, double t_s, const double accel_mps2[3], const double gyro_radps[3]);
    // Separate accelerometer and gyroscope streams, paired at finish(): the
    // gyroscope is interpolated linearly at each accelerometer time.
    void add_accel(size_t line, double t_s, const double accel_mps2[3]);
    void add_gyro(size_t line, double t_s, const double gyro_radps[3]);
    void add_mag(size_t line, double t_s, const double mag_ut[3]);
    // A pressure that is not positive is dropped and counted (one summary issue at finish).
    void add_baro(size_t line, double t_s, double pressure_pa, double temperature_c);
    void add_gnss(size_t line, double t_s, pn_gnss_t fix);  // keeps fix.header.flags
    void add_truth(size_t line, const TruthPoint& point);

    void set_units(StreamId stream, const std::string& found, const std::string& converted);
    bool has_units(StreamId stream) const { return !units_found_[stream].empty(); }

    // A GNSS-only file (pednav_io/gnss_log.hpp) has no IMU samples to require.
    void set_imu_required(bool required) { imu_required_ = required; }

    // Completes the log; throws ReadError when no IMU sample could be read
    // (unless set_imu_required(false)).
    void finish();

private:
    struct Raw3 {
        int64_t t_ns;
        double v[3];
    };
    void pair_accel_gyro();
    double gap_threshold_s(double median_dt_s) const;
    void report_gaps(StreamId stream, const char* label);
    void check_units();

    SensorLog& log_;
    std::string context_;
    std::string stream_context_[stream_count];  // context_ when the stream's samples were added
    ReadOptions options_;
    std::vector<double> times_[stream_count];
    std::vector<size_t> lines_[stream_count];
    size_t bad_[stream_count] = {};
    std::string units_found_[stream_count];
    std::string units_converted_[stream_count];
    std::vector<Raw3> accel_raw_, gyro_raw_;
    bool separate_imu_ = false;
    bool imu_required_ = true;
    struct DuplicateCount {
        size_t count = 0;
        size_t first_line = 0;
    };
    std::map<std::string, DuplicateCount> duplicates_;
    DuplicateCount nonpositive_pressure_;
};

}  // namespace pednav::io::detail
