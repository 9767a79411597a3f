// SPDX-License-Identifier: Apache-2.0
// A recording read a block of records at a time, in memory independent of the
// file's length: what read_sensor_file gives, without holding the file or its
// records. The records come in time order (at equal t_ns IMU, MAG, BARO, GNSS),
// exactly the sequence merged_records(read_sensor_file(path)) holds; the
// warnings come with the same lines and text.
//
// Streamed: the table formats (pednav-csv, x-io, MicroStrain, Xsens, the
// converted Xsens CSV, column-map) and the two-file senslogs pair (its two
// files read side by side). Read whole, then handed out in blocks: the IPIN
// logfile (each sensor clock is placed on the app clock by its smallest delay
// over the whole file). docs/formats.md ("Streaming") says what each summary
// keeps in memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <pednav/pn_types.h>

#include "pednav_io/sensor_log.hpp"

namespace pednav::io {

// One input record of any type; header.type says which member holds it.
union InputRecord {
    pn_record_header_t header;
    pn_imu_t imu;
    pn_mag_t mag;
    pn_baro_t baro;
    pn_gnss_t gnss;
};

// Records of different streams (an IMU row and a magnetometer row of a sparse
// CSV) are held back until their time order is known; at most this many. A
// stream that falls further behind than this loses the rows that can no longer
// be placed in order (each reported by line).
constexpr size_t kMergeWindowRecords = 16384;

class RecordStream {
public:
    // Opens the recording and reads its head (format detection, header,
    // preamble). Throws ReadError as read_sensor_file does for a file that
    // cannot be read at all. merge_window_records 0: no limit. A column map
    // given in options must outlive the stream.
    explicit RecordStream(const std::string& path, const ReadOptions& options = {},
                          size_t merge_window_records = kMergeWindowRecords);
    ~RecordStream();
    RecordStream(const RecordStream&) = delete;
    RecordStream& operator=(const RecordStream&) = delete;

    // Appends up to max_records of the next records to `out`; returns how many
    // (0: the end, log() is complete). When the rest of the file cannot be read
    // (an I/O error, a NUL byte past the first 64 KiB), or at the end when no
    // IMU sample could be read, every record read before is handed out first,
    // then a call throws ReadError (once; 0 after it).
    size_t read(std::vector<InputRecord>& out, size_t max_records);
    bool done() const;

    // What the reader found: format, notes, issues, streams, counts of the
    // records handed out. Issues and notes grow while reading; the streams, the
    // summary issues (gaps, bursts, unit checks, repeated times) and the notes
    // of the end are there once done(). Holds no records: imu, mag, baro and
    // gnss stay empty (SensorLog::records counts them).
    const SensorLog& log() const;

    // Reads ahead to the first IMU record (held for read()); false when the file has none.
    bool first_imu_t_ns(int64_t* t_ns);

    // Progress: bytes of the input read so far, and its size (0 when unknown: a pipe).
    uint64_t bytes_read() const;
    uint64_t bytes_total() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The whole recording read through a RecordStream, keeping only the GNSS fixes
// and the ground truth: the log `pednav inspect` describes, in memory
// independent of the file's length (SensorLog::records counts the rest).
SensorLog scan_sensor_file(const std::string& path, const ReadOptions& options = {});

}  // namespace pednav::io
