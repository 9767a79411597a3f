// SPDX-License-Identifier: Apache-2.0
// x-io Technologies CSV exports (NGIMU "sensors.csv", x-IMU GUI
// "CalInertialAndMag.csv"): headers "Name (unit)", e.g. "Time (s)",
// "Gyroscope X (deg/s)", "Accelerometer X (g)", "Magnetometer X (uT)",
// "Barometer (hPa)". Axes: the sensor frame printed on the case, right-handed;
// kept as the body axes.
#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

struct Column {
    std::string name;  // lower case, without the unit
    std::string unit;  // as written between the parentheses
};

Column parse_column(std::string_view field) {
    field = trim(field);
    Column c;
    const size_t open = field.rfind('(');
    const size_t close = field.rfind(')');
    if (open != std::string_view::npos && close != std::string_view::npos && close > open) {
        c.unit = std::string(trim(field.substr(open + 1, close - open - 1)));
        c.name = to_lower(trim(field.substr(0, open)));
    } else {
        c.name = to_lower(field);
    }
    return c;
}

std::vector<Column> columns_of(const TextFile& file, size_t index) {
    std::vector<Column> out;
    for (auto f : split(file.lines[index], ',')) out.push_back(parse_column(f));
    return out;
}

int index_of(const std::vector<Column>& cols, const std::string& name) {
    for (size_t i = 0; i < cols.size(); ++i) {
        if (cols[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace

bool detect_xio_csv(const TextFile& file) {
    const size_t index = first_content_line(file);
    if (index >= file.lines.size()) return false;
    const auto cols = columns_of(file, index);
    return index_of(cols, "gyroscope x") >= 0 && index_of(cols, "accelerometer x") >= 0;
}

std::unique_ptr<RowReader> open_xio_csv(InputFile& input, const ReadOptions&, LogBuilder& builder, SensorLog& log) {
    const TextFile& file = input.head();
    const size_t index = header_line_index(file, "xio-ngimu-csv");
    const auto cols = columns_of(file, index);
    TableSpec spec;
    spec.delim = ',';
    for (const auto& c : cols) spec.names.push_back(c.name + (c.unit.empty() ? "" : " (" + c.unit + ")"));
    spec.column_count = cols.size();
    spec.first_data_index = index + 1;
    spec.time_col = index_of(cols, "time");
    if (spec.time_col < 0) {
        throw ReadError(file.path, index + 1,
                        "x-io CSV without a \"Time (s)\" column (x-IMU packet numbers need the sample rate: "
                        "use format column-map with time.rate_hz)");
    }
    if (cols[static_cast<size_t>(spec.time_col)].unit != "s") {
        throw ReadError(file.path, index + 1,
                        "x-io CSV time unit '" + cols[static_cast<size_t>(spec.time_col)].unit +
                            "' is not supported (expected s)");
    }
    const char* axes[3] = {" x", " y", " z"};
    for (int i = 0; i < 3; ++i) {
        spec.accel.col[i] = index_of(cols, std::string("accelerometer") + axes[i]);
        spec.gyro.col[i] = index_of(cols, std::string("gyroscope") + axes[i]);
        spec.mag.col[i] = index_of(cols, std::string("magnetometer") + axes[i]);
    }
    if (!spec.accel.present() || !spec.gyro.present()) {
        throw ReadError(file.path, index + 1, "no complete accelerometer and gyroscope X/Y/Z columns");
    }
    const std::string a_unit = cols[static_cast<size_t>(spec.accel.col[0])].unit;
    const std::string g_unit = cols[static_cast<size_t>(spec.gyro.col[0])].unit;
    if (a_unit == "g") {
        spec.accel.scale = kStandardGravity;
    } else if (a_unit != "m/s/s" && a_unit != "m/s^2") {
        throw ReadError(file.path, index + 1, "unknown accelerometer unit '" + a_unit + "'");
    }
    if (g_unit == "deg/s" || g_unit == "\xc2\xb0/s") {
        spec.gyro.scale = kDegToRad;
    } else if (g_unit != "rad/s") {
        throw ReadError(file.path, index + 1, "unknown gyroscope unit '" + g_unit + "'");
    }
    builder.set_units(stream_accel, a_unit, "m/s^2");
    builder.set_units(stream_gyro, g_unit, "rad/s");
    if (spec.mag.present()) {
        const std::string m_unit = cols[static_cast<size_t>(spec.mag.col[0])].unit;
        if (m_unit == "G" || m_unit == "gauss") {
            spec.mag.scale = 100.0;
        } else if (m_unit == "uT" || m_unit == "\xc2\xb5T") {
            spec.mag.scale = 1.0;
        } else {
            builder.issue(index + 1, "magnetometer unit '" + m_unit + "' unknown: magnetometer ignored");
            spec.mag = Vec3Spec{};
        }
        if (spec.mag.present()) builder.set_units(stream_mag, m_unit, "uT");
    } else {
        spec.mag = Vec3Spec{};
    }
    spec.pressure_col = index_of(cols, "barometer");
    if (spec.pressure_col >= 0) {
        const std::string p_unit = cols[static_cast<size_t>(spec.pressure_col)].unit;
        if (p_unit == "hPa") {
            spec.pressure_scale = 100.0;
            builder.set_units(stream_pressure, p_unit, "Pa");
        } else {
            builder.issue(index + 1, "barometer unit '" + p_unit + "' unknown: pressure ignored");
            spec.pressure_col = -1;
        }
    }
    log.axes = "sensor x, y, z as printed on the x-io case (right-handed), not levelled";
    builder.note("x-io CSV: accelerometer in " + a_unit + ", gyroscope in " + g_unit + ", time in s");
    return std::make_unique<TableReader>(input, spec, builder);
}

}  // namespace pednav::io::detail
