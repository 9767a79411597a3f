// SPDX-License-Identifier: Apache-2.0
// Canonical CSV: header naming columns among t,ax,ay,az,gx,gy,gz,mx,my,mz,p
// (s, m/s^2, rad/s, uT, Pa), '#' comments, extra columns ignored, empty
// cells = no sample of that stream at that time (multi-rate files).
#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

const char* const kKnown[] = {"ax", "ay", "az", "gx", "gy", "gz", "mx", "my", "mz", "p"};

std::vector<std::string> header_names(const TextFile& file, size_t index) {
    std::vector<std::string> names;
    for (auto field : split(file.lines[index], ',')) names.push_back(to_lower(trim(field)));
    return names;
}

}  // namespace

bool detect_pednav_csv(const TextFile& file) {
    const size_t index = first_content_line(file);
    if (index >= file.lines.size()) return false;
    const auto names = header_names(file, index);
    if (find_column(names, "t") < 0) return false;
    for (const char* k : kKnown) {
        if (find_column(names, k) >= 0) return true;
    }
    return false;
}

std::unique_ptr<RowReader> open_pednav_csv(InputFile& input, const ReadOptions&, LogBuilder& builder,
                                           SensorLog& log) {
    const TextFile& file = input.head();
    const size_t index = header_line_index(file, "pednav-csv");
    TableSpec spec;
    spec.delim = ',';
    spec.names = header_names(file, index);
    spec.column_count = spec.names.size();
    spec.first_data_index = index + 1;
    spec.time_col = find_column(spec.names, "t");
    spec.empty_cells_mean_absent = true;
    spec.time_unit_from_magnitude = true;
    if (spec.time_col < 0) throw ReadError(file.path, index + 1, "no time column: the header lacks t");
    std::string missing;
    for (const char* k : {"ax", "ay", "az", "gx", "gy", "gz"}) {
        if (find_column(spec.names, k) < 0) missing += std::string(missing.empty() ? "" : ", ") + k;
    }
    if (!missing.empty()) {
        throw ReadError(file.path, index + 1,
                        "no accelerometer/gyroscope columns: the header lacks " + missing);
    }
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
        spec.accel.col[i] = find_column(spec.names, std::string("a") + axes[i]);
        spec.gyro.col[i] = find_column(spec.names, std::string("g") + axes[i]);
        spec.mag.col[i] = find_column(spec.names, std::string("m") + axes[i]);
    }
    if (!spec.mag.present()) spec.mag = Vec3Spec{};
    spec.pressure_col = find_column(spec.names, "p");
    builder.set_units(stream_accel, "m/s^2", "m/s^2");
    builder.set_units(stream_gyro, "rad/s", "rad/s");
    if (spec.mag.present()) builder.set_units(stream_mag, "uT", "uT");
    if (spec.pressure_col >= 0) builder.set_units(stream_pressure, "Pa", "Pa");
    log.axes = "body axes as written in the file (FLU expected)";
    std::string cols;
    for (const auto& n : spec.names) cols += (cols.empty() ? "" : ",") + n;
    builder.note("columns: " + cols);
    return std::make_unique<TableReader>(input, spec, builder);
}

}  // namespace pednav::io::detail
