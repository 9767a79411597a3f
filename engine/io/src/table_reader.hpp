// SPDX-License-Identifier: Apache-2.0
// Internal: reads a delimited table whose columns map to streams, the shape of
// most recordings (one header, one row per sample). A format reader fills a
// TableSpec from the header it recognised; a TableReader reads the rows, a few
// lines at a time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "column_checks.hpp"
#include "formats.hpp"

namespace pednav::io::detail {

// out = R * (scale * in): unit conversion, then the sensor-to-body rotation
// (a signed axis permutation or any rotation matrix, row-major).
struct Vec3Spec {
    int col[3] = {-1, -1, -1};
    double scale = 1.0;
    double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    bool present() const { return col[0] >= 0 && col[1] >= 0 && col[2] >= 0; }
};

struct TableSpec {
    char delim = ',';
    size_t first_data_index = 1;     // 0-based index of the first data row among the file's lines
    size_t column_count = 0;         // fields expected per row
    std::vector<std::string> names;  // column names, for messages

    enum class TimeKind { seconds, counter } time_kind = TimeKind::seconds;
    int time_col = -1;
    double time_scale = 1.0;     // kSeconds: file unit to s
    double counter_rate_hz = 0;  // kCounter: t = counter / rate
    double counter_wrap = 0;     // kSeconds and kCounter: the raw value wraps at this (0 = never)
    // kSeconds: the first time tells a Unix time in ms, us or ns written where
    // seconds belong (1.7e12, 1.7e15, 1.7e18) and sets time_scale for the file.
    bool time_unit_from_magnitude = false;

    Vec3Spec accel, gyro, mag;
    int pressure_col = -1;
    double pressure_scale = 1.0;  // file unit to Pa
    int temperature_col = -1;
    std::vector<int> valid_cols;  // a row with 0 in any of these is skipped (MicroStrain ":valid")

    bool empty_cells_mean_absent = false;  // canonical CSV: empty cells = no sample of that stream
    std::vector<std::string> comment_prefixes = {"#"};
};

class TableReader : public RowReader {
public:
    // Throws ReadError when the spec reads a column the header does not have.
    TableReader(InputFile& input, const TableSpec& spec, LogBuilder& builder);
    bool read_lines(size_t lines) override;
    uint64_t record_types() const override;
    uint64_t bytes_read() const override { return input_.rest().bytes_read(); }
    uint64_t bytes_total() const override { return input_.rest().size_bytes(); }

private:
    void read_row(std::string_view raw, size_t line_no, bool cut);
    void end();

    InputFile& input_;
    LineCursor lines_;
    TableSpec spec_;  // time_scale may be settled by the first time
    LogBuilder& builder_;
    bool time_scale_settled_;
    unsigned present_ = 0;
    Clock clock_{""}, imu_clock_{"accel/gyro"}, mag_clock_{"mag"}, pressure_clock_{"pressure"};
    std::vector<std::string_view> fields_;
    // Plausibility per inertial column: accelerometer beyond 1000 m/s^2 (100 g)
    // or flat above 2 g, gyroscope beyond 50 rad/s (2 900 deg/s) or flat above 2 rad/s.
    std::vector<ColumnCheck> checks_;
    double last_raw_time_ = 0.0, wrap_offset_ = 0.0;
    bool have_raw_time_ = false;
    size_t last_line_ = 0;       // number of the last line of the file read so far
    size_t truncated_line_ = 0;  // the last row with too few or too many fields
    bool ended_ = false;
};

// Rotation matrices for the common remaps.
void set_identity(double R[9]);
void set_signed_permutation(double R[9], const int src[3], const double sign[3]);

constexpr double kStandardGravity = 9.80665;
constexpr double kDegToRad = 0.017453292519943295;

}  // namespace pednav::io::detail
