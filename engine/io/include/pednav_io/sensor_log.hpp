// SPDX-License-Identifier: Apache-2.0
// Readers: one call turns a recording into engine records (SI units, the
// sensor's own right-handed axes, t_ns from the file's own time origin), plus
// what was detected and what was wrong with the file. docs/formats.md lists
// every format, its detection rule and its unit and axis conversions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <pednav/pn_types.h>
#include <nlohmann/json_fwd.hpp>

#include "pednav_io/origin.hpp"

namespace pednav::io {

// A problem in the file that reading continued past: a bad row, a gap, a
// duplicate, a unit that looks wrong. line is 1-based; 0 = the whole file.
struct ReadIssue {
    size_t line;
    std::string message;
};

// One stream of the file: "accel", "gyro", "mag", "pressure", "gnss", "truth".
struct StreamInfo {
    std::string name;
    size_t count = 0;             // samples kept
    double rate_hz = 0.0;         // mean rate: (count - 1) / duration_s
    double median_rate_hz = 0.0;  // 1 / median interval: the sensor's own rate when samples were lost
    double duration_s = 0.0;      // last sample time - first sample time
    double t_first_s = 0.0;       // time of the first sample kept (file's own time origin)
    double t_last_s = 0.0;        // time of the last sample kept
    std::string units_found;      // unit in the file, e.g. "g", "deg/s", "gauss", "hPa"
    std::string units_converted;  // unit handed to the engine, e.g. "m/s^2"
    size_t gaps = 0;              // intervals longer than ReadOptions::gap_s
    size_t bad_rows = 0;          // rows or samples of this stream skipped
};

// A ground-truth point read from the file (e.g. IPIN POSI). Lat/lon points are
// converted to local ENU metres around SensorLog::truth_origin.
struct TruthPoint {
    double t_s;
    double x_m, y_m, z_m;
    int floor;
    bool has_z;
    std::string label;
};

// Records read per type: the sizes of SensorLog's vectors when it holds the
// records, and the only record of them when it does not (RecordStream).
struct RecordCounts {
    size_t imu = 0;
    size_t mag = 0;
    size_t baro = 0;
    size_t gnss = 0;
    int64_t imu_first_t_ns = 0;  // time of the first IMU record, when imu > 0
};

struct SensorLog {
    std::string format;  // e.g. "pednav-csv", "xio-ngimu-csv", "microstrain-sensorconnect-a"
    std::string path;
    std::vector<pn_imu_t> imu;
    std::vector<pn_mag_t> mag;
    std::vector<pn_baro_t> baro;
    std::vector<pn_gnss_t> gnss;
    std::vector<TruthPoint> truth;
    std::vector<StreamInfo> streams;
    std::vector<ReadIssue> issues;   // bad rows, gaps, duplicates, unit notes; reading continued past them
    std::vector<std::string> notes;  // what was detected: format, rate, units, columns, axes
    Origin truth_origin;             // origin of the truth points when they came as lat/lon
    std::string axes;                // the body axes of the records, e.g. "sensor x,y,z (NGIMU case)"
    size_t issues_not_listed = 0;    // issues beyond ReadOptions::max_issues: counted, not kept in `issues`
    int64_t utc_ns_at_zero = 0;      // UTC (ns since 1970) of t = 0 when the file tells it (NMEA dates), else 0
    RecordCounts records;            // records read, per type

    const StreamInfo* stream(const std::string& name) const;
};

struct ReadOptions {
    std::string format = "auto";                 // a name from supported_formats(), or "auto"
    const nlohmann::json* column_map = nullptr;  // for format "column-map" (see docs/formats.md)
    double gap_s = 1.0;                          // intervals longer than this are reported as gaps
    size_t max_issues = 200;                     // issues kept in SensorLog::issues; the rest are counted
    // Sample rate of a packet-counter time column (Xsens PacketCounter), Hz;
    // 0 = from the file's preamble. Given, it wins over the preamble.
    double counter_rate_hz = 0.0;
};

// Fatal: missing, empty, binary or unrecognised file, or no accelerometer and
// gyroscope. what() names the file, the line (when there is one) and the reason.
class ReadError : public std::runtime_error {
public:
    ReadError(const std::string& path, size_t line, const std::string& reason);
    const std::string& path() const { return path_; }
    size_t line() const { return line_; }
    const std::string& reason() const { return reason_; }

private:
    std::string path_;
    size_t line_;
    std::string reason_;
};

// Reads a recording. `path` is a file or, for two-file formats (humolire), the
// folder or either file. Throws ReadError on fatal problems.
SensorLog read_sensor_file(const std::string& path, const ReadOptions& options = {});

// Every input record in time order; at equal t_ns: IMU, MAG, BARO, GNSS (stable).
// The pointers point into `log`, which must outlive the vector.
std::vector<const pn_record_header_t*> merged_records(const SensorLog& log);
// The same for streams held elsewhere (each already in time order).
std::vector<const pn_record_header_t*> merged_records(const std::vector<pn_imu_t>& imu,
                                                      const std::vector<pn_mag_t>& mag,
                                                      const std::vector<pn_baro_t>& baro,
                                                      const std::vector<pn_gnss_t>& gnss);

// Format names accepted by ReadOptions::format (besides "auto").
std::vector<std::string> supported_formats();

// The name of the format `path` would be read as with format "auto"; throws ReadError.
std::string detect_format(const std::string& path);

}  // namespace pednav::io
