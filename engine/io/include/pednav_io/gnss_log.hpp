// SPDX-License-Identifier: Apache-2.0
// GNSS readers: a receiver's log (NMEA 0183) or a CSV of fixes becomes
// pn_gnss_t records (WGS-84 degrees, ellipsoidal height, 1-sigma accuracies in
// metres, ENU velocity in m/s) on the clock of the IMU log they go with.
// docs/formats.md ("GNSS input") gives the formats, the time base and how each
// field of a record is made.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io {

// How NMEA times (UTC) are put on the IMU log's clock. The CSV's `t` already
// is on that clock and ignores this.
struct GnssTimeBase {
    // The first epoch of the file (its first sentence with a time, fix or not)
    // is at this t, in seconds on the IMU clock: the two logs started together.
    double first_epoch_t_s = 0.0;
    // When non-zero: the UTC (ns since 1970) of t = 0 on the IMU clock, an exact
    // mapping that wins over first_epoch_t_s.
    int64_t utc_ns_at_zero = 0;
};

struct GnssReadOptions {
    std::string format = "auto";  // "auto", or a name from supported_gnss_formats()
    GnssTimeBase time;
    // 1-sigma user equivalent range error of the receiver: without a GST
    // sentence, h_accuracy_m = HDOP x uere_m and v_accuracy_m = VDOP x uere_m.
    double uere_m = 5.0;
    double gap_s = 3.0;       // fix intervals longer than this are reported as gaps
    size_t max_issues = 200;  // issues kept in SensorLog::issues; the rest are counted
};

// v_accuracy_m of a fix that carries no height (a CSV row without `alt`, an
// NMEA RMC-only epoch, a 2D fix): height_m is then 0 (or the receiver's held
// value) and this accuracy gives it no weight.
constexpr double kGnssNoHeightAccuracy_m = 1.0e4;

// Reads a GNSS file into a SensorLog holding only `gnss` records, the "gnss"
// stream, issues (bad sentences or rows by line) and notes. Throws ReadError
// (path:line: reason) when the file is missing, empty, binary, of an unknown
// format, or holds no fix at all.
SensorLog read_gnss_file(const std::string& path, const GnssReadOptions& options = {});

// "nmea" or "csv": what read_gnss_file would read `path` as with format
// "auto". Throws ReadError when it is neither.
std::string detect_gnss_format(const std::string& path);

std::vector<std::string> supported_gnss_formats();

// `log` takes the fixes of `gnss` (read by read_gnss_file) in place of its own
// GNSS records and stream; a note says how many of its own were replaced.
// gnss's issues stay in gnss (their lines are of the GNSS file).
void use_gnss(SensorLog& log, const SensorLog& gnss);

// What a stream of fixes holds (`pednav inspect`, the "gnss_fixes" key of
// its JSON): count, fix types, satellites min/median/max, horizontal
// accuracy median and max, fixes with velocity, the UTC of the first fix.
nlohmann::json gnss_fixes_json(const std::vector<pn_gnss_t>& fixes);

// ISO 8601 UTC with milliseconds, "2024-05-01T10:00:00.000Z".
std::string iso_utc(int64_t utc_ns);

// A UTC instant given as Unix seconds ("1714557600.25") or ISO 8601
// ("2024-05-01T10:00:00Z", "2024-05-01T10:00:00.5Z"); false when it is neither.
bool parse_utc(const std::string& text, int64_t* utc_ns);

}  // namespace pednav::io
