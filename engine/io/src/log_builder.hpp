// SPDX-License-Identifier: Apache-2.0
// Internal: what every reader shares. A reader parses its layout and hands
// samples, already in SI units and body axes, to a LogBuilder, which checks time
// order, drops duplicates, counts bad rows and gaps, pairs separate accelerometer
// and gyroscope streams, checks unit sanity and fills SensorLog::streams.
// Records go to a RecordSink as soon as they are made (the gyroscope of a
// separate pair once the samples around each accelerometer time are known);
// what the summaries at finish() need is kept in SpillVectors, so a builder
// holds memory independent of the file's length.
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "pednav_io/sensor_log.hpp"
#include "record_sink.hpp"
#include "spill_vector.hpp"

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
    // Records go to `sink`, or to log.imu, log.mag, log.baro, log.gnss when it is null.
    LogBuilder(SensorLog& log, const ReadOptions& options, RecordSink* sink = nullptr);

    void note(const std::string& text);
    // Prefix for issue messages while reading one file of a multi-file recording.
    void set_context(const std::string& context) { context_ = context; }
    // Issues go to list `channel` (0 .. kChannels - 1) until finish(), which
    // puts the lists one after the other: a reader of two files read side by
    // side lists each file's issues together, as if read one after the other.
    void set_channel(int channel) { channel_ = channel; }
    static constexpr int kChannels = 3;
    void issue(size_t line, const std::string& message);
    // The row (or sample) is skipped; counted as a bad row of every stream in
    // `streams`. The issue reads "<unit> skipped: <message>".
    void bad_row(size_t line, const std::string& message, unsigned streams, const char* unit = "row");
    // True when a row/sample at t_s is to be kept: going backwards is a bad row,
    // a repeated time is dropped and counted (one summary issue at finish).
    bool accept_time(Clock& clock, size_t line, double t_s, unsigned streams);

    void add_imu(size_t line, double t_s, const double accel_mps2[3], const double gyro_radps[3]);
    // Separate accelerometer and gyroscope streams, paired as they come: the
    // gyroscope is interpolated linearly at each accelerometer time.
    void add_accel(size_t line, double t_s, const double accel_mps2[3]);
    void add_gyro(size_t line, double t_s, const double gyro_radps[3]);
    // No more samples of stream_accel or stream_gyro will come (finish() says it for both).
    void end_of(StreamId stream);
    // Accelerometer samples wait for the gyroscope sample after them.
    bool pairing_waits() const { return !accel_raw_.empty(); }
    void add_mag(size_t line, double t_s, const double mag_ut[3]);
    // A pressure that is not positive is dropped and counted (one summary issue at finish).
    void add_baro(size_t line, double t_s, double pressure_pa, double temperature_c);
    void add_gnss(size_t line, double t_s, pn_gnss_t fix);  // keeps fix.header.flags
    void add_truth(size_t line, const TruthPoint& point);

    void set_units(StreamId stream, const std::string& found, const std::string& converted);
    bool has_units(StreamId stream) const { return !units_found_[stream].empty(); }

    // A GNSS-only file (pednav_io/gnss_log.hpp) has no IMU samples to require.
    void set_imu_required(bool required) { imu_required_ = required; }

    // An IMU record has been handed to the sink.
    bool has_imu() const { return log_.records.imu > 0; }

    // Completes the log; throws ReadError when no IMU sample could be read
    // (unless set_imu_required(false)).
    void finish();

private:
    struct Raw3 {
        int64_t t_ns;
        size_t line;
        double v[3];
    };
    // A sample's time and line: what the gap, burst and rate summaries read back.
    struct TimeLine {
        double t_s;
        uint64_t line;
    };
    struct Intervals {
        bool known = false;
        double median_dt_s = 0.0;
    };
    struct DuplicateCount {
        size_t count = 0;
        size_t first_line = 0;
    };

    // Records of a stream skipped when they can no longer be placed in time order.
    bool placeable(pn_record_type_t type, int64_t t_ns, size_t line, StreamId stream);
    void emit(const InputRecord& record);
    void add_sample(StreamId stream, size_t line, double t_s);
    SpillVector<TimeLine>& samples(StreamId stream);
    // Pairs the accelerometer samples whose surrounding gyroscope samples are
    // known (all of them once the gyroscope has ended).
    void pair_accel_gyro();
    double median_interval_s(StreamId stream);
    double gap_threshold_s(double median_dt_s) const;
    void report_gaps(StreamId stream, const char* label);
    void check_units();
    void merge_channels();

    SensorLog& log_;
    std::unique_ptr<RecordSink> own_sink_;
    RecordSink* sink_;
    std::string context_;
    std::string stream_context_[stream_count];  // context_ when the stream's samples were added
    int channel_ = 0;
    std::vector<ReadIssue> channel_issues_[kChannels];
    size_t channel_not_listed_[kChannels] = {};
    ReadOptions options_;
    SpillVector<TimeLine> samples_[stream_count];
    Intervals intervals_[stream_count];
    bool imu_rows_ = false;  // add_imu: the gyroscope's samples are the accelerometer's
    SpillVector<double> accel_norm_, gyro_norm_, mag_norm_, pressure_;
    size_t bad_[stream_count] = {};
    std::string units_found_[stream_count];
    std::string units_converted_[stream_count];
    std::deque<Raw3> accel_raw_;  // not yet paired, in time order
    std::deque<Raw3> gyro_raw_;   // from the last one at or before accel_raw_.front()
    size_t paired_ = 0, outside_ = 0;
    bool accel_ended_ = false, gyro_ended_ = false;
    int64_t last_accel_t_ns_ = 0;
    bool have_first_gyro_ = false;
    int64_t first_gyro_t_ns_ = 0;
    bool separate_imu_ = false;
    bool imu_required_ = true;
    std::map<std::string, DuplicateCount> duplicates_;
    DuplicateCount nonpositive_pressure_;
};

}  // namespace pednav::io::detail
