// SPDX-License-Identifier: Apache-2.0
// Internal: reads a delimited table whose columns map to streams, the shape of
// most recordings (one header, one row per sample). A format reader fills a
// TableSpec from the header it recognised; read_table does the rest.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "log_builder.hpp"
#include "text_file.hpp"

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
    size_t first_data_index = 1;     // 0-based index in TextFile::lines of the first data row
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

void read_table(const TextFile& file, const TableSpec& spec, LogBuilder& builder);

// Rotation matrices for the common remaps.
void set_identity(double R[9]);
void set_signed_permutation(double R[9], const int src[3], const double sign[3]);

constexpr double kStandardGravity = 9.80665;
constexpr double kDegToRad = 0.017453292519943295;

}  // namespace pednav::io::detail
