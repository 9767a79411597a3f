// SPDX-License-Identifier: Apache-2.0
// LORD MicroStrain SensorConnect CSV exports. Columns are "<device>:<channel>"
// (e.g. "inertial-6253.76535:scaledAccelX") with an optional ":valid" flag
// column after a channel.
//   layout A: scaledAccelX/Y/Z (g), scaledGyroX/Y/Z (rad/s), scaledMagX/Y/Z (gauss)
//   layout B: estCompensatedAccelX/Y/Z (m/s^2), estAngularRateX/Y/Z (rad/s), ":valid" flags
// Axes: the 3DM-GX5 case frame is x forward, y right, z down; it is turned
// 180 degrees about x into forward-left-up: (x, -y, -z).
#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

struct Header {
    std::vector<std::string> names;     // full names
    std::vector<std::string> channels;  // channel part, with ":valid" kept
};

Header header_of(const TextFile& file, size_t index) {
    Header h;
    for (auto f : split(file.lines[index], ',')) {
        const std::string name(trim(f));
        h.names.push_back(name);
        const size_t colon = name.find(':');
        h.channels.push_back(colon == std::string::npos ? name : name.substr(colon + 1));
    }
    return h;
}

bool has_channel(const TextFile& file, const char* channel) {
    const size_t index = first_content_line(file);
    if (index >= file.lines.size()) return false;
    const Header h = header_of(file, index);
    return find_column(h.channels, "Time") == 0 && find_column(h.channels, channel) >= 0;
}

}  // namespace

bool detect_microstrain_a(const TextFile& file) { return has_channel(file, "scaledAccelX"); }
bool detect_microstrain_b(const TextFile& file) { return has_channel(file, "estCompensatedAccelX"); }

std::unique_ptr<RowReader> open_microstrain(InputFile& input, const ReadOptions&, LogBuilder& builder,
                                            SensorLog& log) {
    const TextFile& file = input.head();
    const size_t index = header_line_index(file, "microstrain-sensorconnect");
    const Header h = header_of(file, index);
    TableSpec spec;
    spec.delim = ',';
    spec.names = h.names;
    spec.column_count = h.names.size();
    spec.first_data_index = index + 1;
    spec.time_col = find_column(h.channels, "Time");

    const bool layout_a = find_column(h.channels, "scaledAccelX") >= 0;
    const char* accel = layout_a ? "scaledAccel" : "estCompensatedAccel";
    const char* gyro = layout_a ? "scaledGyro" : "estAngularRate";
    const char* xyz[3] = {"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i) {
        spec.accel.col[i] = find_column(h.channels, std::string(accel) + xyz[i]);
        spec.gyro.col[i] = find_column(h.channels, std::string(gyro) + xyz[i]);
        spec.mag.col[i] = find_column(h.channels, std::string("scaledMag") + xyz[i]);
        for (const char* base : {accel, gyro}) {
            const int v = find_column(h.channels, std::string(base) + xyz[i] + ":valid");
            if (v >= 0) spec.valid_cols.push_back(v);
        }
    }
    if (!spec.accel.present() || !spec.gyro.present()) {
        throw ReadError(file.path, index + 1,
                        std::string("no complete ") + accel + "X/Y/Z and " + gyro + "X/Y/Z columns");
    }
    if (!spec.mag.present()) spec.mag = Vec3Spec{};

    // Forward-right-down case axes to forward-left-up: a proper rotation.
    const int src[3] = {0, 1, 2};
    const double sign[3] = {1.0, -1.0, -1.0};
    set_signed_permutation(spec.accel.R, src, sign);
    set_signed_permutation(spec.gyro.R, src, sign);
    set_signed_permutation(spec.mag.R, src, sign);

    if (layout_a) {
        spec.accel.scale = kStandardGravity;
        builder.set_units(stream_accel, "g", "m/s^2");
    } else {
        builder.set_units(stream_accel, "m/s^2", "m/s^2");
    }
    builder.set_units(stream_gyro, "rad/s", "rad/s");
    if (spec.mag.present()) {
        spec.mag.scale = 100.0;  // gauss to microtesla
        builder.set_units(stream_mag, "gauss", "uT");
    }
    spec.pressure_col = find_column(h.channels, "scaledAmbientPressure");
    if (spec.pressure_col >= 0) {
        spec.pressure_scale = 100.0;  // mbar to Pa
        builder.set_units(stream_pressure, "mbar", "Pa");
    }
    log.axes =
        "3DM-GX5 case axes turned from forward-right-down to forward-left-up: (x, -y, -z); not levelled";
    builder.note(std::string("MicroStrain SensorConnect layout ") + (layout_a ? "A" : "B") + ": " + accel +
                 " in " + (layout_a ? "g" : "m/s^2") + ", " + gyro + " in rad/s" +
                 (spec.valid_cols.empty() ? "" : ", rows with a ':valid' flag of 0 skipped"));
    return std::make_unique<TableReader>(input, spec, builder);
}

}  // namespace pednav::io::detail
