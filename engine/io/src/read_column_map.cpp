// SPDX-License-Identifier: Apache-2.0
// Any delimited file described by a column map (docs/formats.md, "column-map"):
// which column is what, its unit, and the sensor-to-body rotation. Keys are
// checked strictly: an unknown key is an error naming its JSON pointer.
#include <cmath>
#include <cstdio>
#include <set>

#include <nlohmann/json.hpp>

#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

using nlohmann::json;

struct MapError {
    std::string pointer;
    std::string message;
};

[[noreturn]] void fail(const std::string& pointer, const std::string& message) {
    throw MapError{pointer, message};
}

void check_keys(const json& object, const std::string& pointer, std::initializer_list<const char*> allowed) {
    if (!object.is_object()) fail(pointer, "must be an object");
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool ok = false;
        for (const char* key : allowed) ok = ok || it.key() == key;
        if (!ok) fail(pointer + "/" + it.key(), "unknown key");
    }
}

int resolve_column(const json& ref, const std::vector<std::string>& names, const std::string& pointer) {
    if (ref.is_number_integer()) {
        const int index = ref.get<int>();
        if (index < 0 || (!names.empty() && static_cast<size_t>(index) >= names.size())) {
            fail(pointer, "column index " + std::to_string(index) + " out of range");
        }
        return index;
    }
    if (ref.is_string()) {
        const int index = find_column(names, ref.get<std::string>());
        if (index < 0) fail(pointer, "no column named '" + ref.get<std::string>() + "' in the header");
        return index;
    }
    fail(pointer, "a column is a header name or a 0-based index");
}

std::string unit_of(const json& object, const std::string& pointer, const char* fallback) {
    if (!object.contains("unit")) return fallback;
    if (!object["unit"].is_string()) fail(pointer + "/unit", "must be a string");
    return object["unit"].get<std::string>();
}

double number_of(const json& object, const char* key, const std::string& pointer, double fallback) {
    if (!object.contains(key)) return fallback;
    if (!object[key].is_number()) fail(pointer + "/" + key, "must be a number");
    const double v = object[key].get<double>();
    if (!std::isfinite(v) || v <= 0) fail(pointer + "/" + key, "must be a positive number");
    return v;
}

void read_vec(const json& object, const std::string& pointer, const std::vector<std::string>& names,
              Vec3Spec* v) {
    if (!object.contains("columns") || !object["columns"].is_array() || object["columns"].size() != 3) {
        fail(pointer + "/columns", "must list 3 columns (x, y, z of the sensor)");
    }
    for (int i = 0; i < 3; ++i) {
        v->col[i] = resolve_column(object["columns"][static_cast<size_t>(i)], names,
                                   pointer + "/columns/" + std::to_string(i));
    }
}

// "x=-y, y=x, z=z": body axis = signed sensor axis.
void parse_axes(const std::string& text, double R[9], const std::string& pointer) {
    for (int i = 0; i < 9; ++i) R[i] = 0.0;
    bool seen_body[3] = {false, false, false}, seen_src[3] = {false, false, false};
    for (auto part : split(text, ',')) {
        part = trim(part);
        const size_t eq = part.find('=');
        if (eq == std::string_view::npos) fail(pointer, "each part is body=±sensor, e.g. \"x=-y\"");
        const std::string body = to_lower(trim(part.substr(0, eq)));
        std::string src = to_lower(trim(part.substr(eq + 1)));
        double sign = 1.0;
        if (!src.empty() && (src[0] == '-' || src[0] == '+')) {
            sign = src[0] == '-' ? -1.0 : 1.0;
            src = std::string(trim(src.substr(1)));
        }
        if (body.size() != 1 || src.size() != 1 || body[0] < 'x' || body[0] > 'z' || src[0] < 'x' ||
            src[0] > 'z') {
            fail(pointer, "cannot read '" + std::string(part) + "'");
        }
        const int b = body[0] - 'x', s = src[0] - 'x';
        if (seen_body[b] || seen_src[s]) fail(pointer, "each axis must appear once on each side");
        seen_body[b] = seen_src[s] = true;
        R[b * 3 + s] = sign;
    }
    if (!(seen_body[0] && seen_body[1] && seen_body[2])) fail(pointer, "give x, y and z");
}

void quaternion_to_matrix(const json& q, double R[9], const std::string& pointer) {
    if (!q.is_array() || q.size() != 4) fail(pointer, "must be [w, x, y, z]");
    double v[4];
    for (size_t i = 0; i < 4; ++i) {
        if (!q[i].is_number()) fail(pointer, "must be [w, x, y, z] numbers");
        v[i] = q[i].get<double>();
    }
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
    if (!(n > 0.5 && n < 1.5)) fail(pointer, "is not a unit quaternion");
    const double w = v[0] / n, x = v[1] / n, y = v[2] / n, z = v[3] / n;
    const double M[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
                         2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                         2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
    for (int i = 0; i < 9; ++i) R[i] = M[i];
}

double determinant(const double R[9]) {
    return R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
           R[2] * (R[3] * R[7] - R[4] * R[6]);
}

std::unique_ptr<RowReader> apply_map(InputFile& input, const json& map, LogBuilder& builder, SensorLog& log) {
    check_keys(map, "",
               {"delimiter", "header_line", "comment_prefixes", "time", "accel", "gyro", "mag", "pressure",
                "axes", "rotation_q_body_from_sensor", "description"});
    TableSpec spec;
    // Header.
    size_t header_index = first_content_line(input.head());
    if (map.contains("header_line")) {
        if (!map["header_line"].is_number_integer() || map["header_line"].get<int>() < 0) {
            fail("/header_line", "must be a 1-based line number, or 0 when the file has no header");
        }
        const int h = map["header_line"].get<int>();
        header_index = h == 0 ? std::string::npos : static_cast<size_t>(h - 1);
        if (h > 0) input.extend_head(static_cast<size_t>(h));  // a header further down than the head
    }
    const TextFile& file = input.head();
    if (map.contains("comment_prefixes")) {
        spec.comment_prefixes.clear();
        for (const auto& p : map["comment_prefixes"]) {
            if (!p.is_string()) fail("/comment_prefixes", "must be a list of strings");
            spec.comment_prefixes.push_back(p.get<std::string>());
        }
    }
    const std::string_view header_text =
        header_index == std::string::npos
            ? (first_content_line(file) < file.lines.size() ? file.lines[first_content_line(file)]
                                                            : std::string_view())
            : (header_index < file.lines.size() ? file.lines[header_index] : std::string_view());
    spec.delim = guess_delimiter(header_text);
    if (map.contains("delimiter")) {
        const json& d = map["delimiter"];
        if (!d.is_string() || d.get<std::string>().size() != 1) fail("/delimiter", "must be one character");
        spec.delim = d.get<std::string>()[0];
    }
    const auto header_fields = split(header_text, spec.delim);
    if (header_index == std::string::npos) {
        for (size_t i = 0; i < header_fields.size(); ++i) spec.names.push_back("column " + std::to_string(i));
        spec.first_data_index = 0;
    } else {
        if (header_index >= file.lines.size()) fail("/header_line", "is past the end of the file");
        for (auto f : header_fields) spec.names.emplace_back(trim(f));
        spec.first_data_index = header_index + 1;
    }
    spec.column_count = spec.names.size();

    // Time.
    if (!map.contains("time")) fail("/time", "is required");
    const json& time = map["time"];
    check_keys(time, "/time", {"column", "unit", "scale_s", "rate_hz", "wrap"});
    if (!time.contains("column")) fail("/time/column", "is required");
    spec.time_col = resolve_column(time["column"], spec.names, "/time/column");
    spec.counter_wrap = time.contains("wrap") ? number_of(time, "wrap", "/time", 0.0) : 0.0;
    std::string time_text;
    if (time.contains("rate_hz")) {
        spec.time_kind = TableSpec::TimeKind::counter;
        spec.counter_rate_hz = number_of(time, "rate_hz", "/time", 0.0);
        char text[96];
        std::snprintf(text, sizeof text, "sample counter / %.6g Hz", spec.counter_rate_hz);
        time_text = text;
    } else if (time.contains("scale_s")) {
        spec.time_scale = number_of(time, "scale_s", "/time", 1.0);
        char text[96];
        std::snprintf(text, sizeof text, "ticks of %.6g s", spec.time_scale);
        time_text = text;
    } else {
        const std::string unit = unit_of(time, "/time", "s");
        if (unit == "s")
            spec.time_scale = 1.0;
        else if (unit == "ms")
            spec.time_scale = 1e-3;
        else if (unit == "us")
            spec.time_scale = 1e-6;
        else if (unit == "ns")
            spec.time_scale = 1e-9;
        else
            fail("/time/unit", "unknown unit '" + unit + "' (s, ms, us, ns; or give scale_s or rate_hz)");
        time_text = unit;
    }

    // Streams.
    if (!map.contains("accel") || !map.contains("gyro")) {
        fail(map.contains("accel") ? "/gyro" : "/accel", "is required (accelerometer and gyroscope)");
    }
    const json& accel = map["accel"];
    check_keys(accel, "/accel", {"columns", "unit", "gravity_mps2"});
    read_vec(accel, "/accel", spec.names, &spec.accel);
    const std::string a_unit = unit_of(accel, "/accel", "m/s^2");
    if (a_unit == "g")
        spec.accel.scale = number_of(accel, "gravity_mps2", "/accel", kStandardGravity);
    else if (a_unit != "m/s^2")
        fail("/accel/unit", "unknown unit '" + a_unit + "' (m/s^2 or g)");
    builder.set_units(stream_accel, a_unit, "m/s^2");

    const json& gyro = map["gyro"];
    check_keys(gyro, "/gyro", {"columns", "unit"});
    read_vec(gyro, "/gyro", spec.names, &spec.gyro);
    const std::string g_unit = unit_of(gyro, "/gyro", "rad/s");
    if (g_unit == "deg/s")
        spec.gyro.scale = kDegToRad;
    else if (g_unit != "rad/s")
        fail("/gyro/unit", "unknown unit '" + g_unit + "' (rad/s or deg/s)");
    builder.set_units(stream_gyro, g_unit, "rad/s");

    if (map.contains("mag")) {
        const json& mag = map["mag"];
        check_keys(mag, "/mag", {"columns", "unit", "normalised_field_ut"});
        read_vec(mag, "/mag", spec.names, &spec.mag);
        const std::string m_unit = unit_of(mag, "/mag", "uT");
        if (m_unit == "uT")
            spec.mag.scale = 1.0;
        else if (m_unit == "gauss")
            spec.mag.scale = 100.0;
        else if (m_unit == "mG")
            spec.mag.scale = 0.1;
        else if (m_unit == "nT")
            spec.mag.scale = 1e-3;
        else if (m_unit == "normalised")
            spec.mag.scale = number_of(mag, "normalised_field_ut", "/mag", 50.0);
        else
            fail("/mag/unit", "unknown unit '" + m_unit + "' (uT, gauss, mG, nT, normalised)");
        builder.set_units(stream_mag, m_unit == "normalised" ? "normalised a.u." : m_unit, "uT");
    }
    if (map.contains("pressure")) {
        const json& p = map["pressure"];
        check_keys(p, "/pressure", {"column", "unit"});
        if (!p.contains("column")) fail("/pressure/column", "is required");
        spec.pressure_col = resolve_column(p["column"], spec.names, "/pressure/column");
        const std::string p_unit = unit_of(p, "/pressure", "Pa");
        if (p_unit == "Pa")
            spec.pressure_scale = 1.0;
        else if (p_unit == "hPa" || p_unit == "mbar")
            spec.pressure_scale = 100.0;
        else if (p_unit == "kPa")
            spec.pressure_scale = 1000.0;
        else
            fail("/pressure/unit", "unknown unit '" + p_unit + "' (Pa, hPa, mbar, kPa)");
        builder.set_units(stream_pressure, p_unit, "Pa");
    }

    // Sensor-to-body rotation, the same for every vector stream.
    double R[9];
    set_identity(R);
    std::string axes_text = "sensor axes as in the file";
    if (map.contains("axes") && map.contains("rotation_q_body_from_sensor")) {
        fail("/axes", "give either axes or rotation_q_body_from_sensor, not both");
    }
    if (map.contains("axes")) {
        if (!map["axes"].is_string()) fail("/axes", "must be a string such as \"x=-y, y=x, z=z\"");
        parse_axes(map["axes"].get<std::string>(), R, "/axes");
        axes_text = "body " + map["axes"].get<std::string>() + " (sensor axes)";
    } else if (map.contains("rotation_q_body_from_sensor")) {
        quaternion_to_matrix(map["rotation_q_body_from_sensor"], R, "/rotation_q_body_from_sensor");
        axes_text = "sensor axes rotated by rotation_q_body_from_sensor";
    }
    if (determinant(R) < 0) {
        builder.issue(0,
                      "the axis remap is a reflection (determinant -1): right only if the file's axes are "
                      "left-handed");
    }
    for (Vec3Spec* v : {&spec.accel, &spec.gyro, &spec.mag}) {
        for (int i = 0; i < 9; ++i) v->R[i] = R[i];
    }
    log.axes = axes_text;
    builder.note("column map: time " + time_text + ", accelerometer " + a_unit + ", gyroscope " + g_unit);
    return std::make_unique<TableReader>(input, spec, builder);
}

}  // namespace

std::unique_ptr<RowReader> open_with_column_map(InputFile& input, const json& map, LogBuilder& builder,
                                                SensorLog& log) {
    const json& inner = (map.is_object() && map.contains("column_map")) ? map["column_map"] : map;
    try {
        return apply_map(input, inner, builder, log);
    } catch (const MapError& e) {
        throw ReadError(
            input.path(), 0,
            "column map " + (e.pointer.empty() ? std::string("/") : e.pointer) + ": " + e.message);
    }
}

bool detect_column_map(const TextFile&) { return false; }

std::unique_ptr<RowReader> open_column_map(InputFile& input, const ReadOptions& options, LogBuilder& builder,
                                           SensorLog& log) {
    if (options.column_map == nullptr) {
        throw ReadError(input.path(), 0,
                        "format column-map needs a column map (ReadOptions::column_map / --column-map)");
    }
    return open_with_column_map(input, *options.column_map, builder, log);
}

namespace {

// Rows read by another RowReader, and a note once they have ended.
class NoteAtEnd : public RowReader {
public:
    NoteAtEnd(std::unique_ptr<RowReader> rows, LogBuilder& builder, std::string note)
        : rows_(std::move(rows)), builder_(builder), note_(std::move(note)) {}
    bool read_lines(size_t lines) override {
        if (rows_->read_lines(lines)) return true;
        if (!note_.empty()) builder_.note(note_);
        note_.clear();
        return false;
    }
    uint64_t record_types() const override { return rows_->record_types(); }
    uint64_t bytes_read() const override { return rows_->bytes_read(); }
    uint64_t bytes_total() const override { return rows_->bytes_total(); }

private:
    std::unique_ptr<RowReader> rows_;
    LogBuilder& builder_;
    std::string note_;
};

}  // namespace

// The biba-chest-xsens author's conversion of an Xsens MT Manager export:
// time = SampleTimeFine ticks, gx = Gyr_Z, gy = Gyr_Y, gz = Gyr_X, a = Acc / 9.70
// with the same x/z swap, m = Mag unchanged (normalised), p in hPa. The map
// below undoes it, giving the raw export's Xsens sensor axes and m/s^2.
bool detect_biba_converted_csv(const TextFile& file) {
    const size_t index = first_content_line(file);
    return index < file.lines.size() && trim(file.lines[index]) == "time,gx,gy,gz,ax,ay,az,mx,my,mz,p";
}

std::unique_ptr<RowReader> open_biba_converted_csv(InputFile& input, const ReadOptions&, LogBuilder& builder,
                                                   SensorLog& log) {
    static const json map = {
        {"delimiter", ","},
        {"time", {{"column", "time"}, {"scale_s", 1e-4}, {"wrap", 4294967296.0}}},
        {"accel", {{"columns", {"az", "ay", "ax"}}, {"unit", "g"}, {"gravity_mps2", 9.70}}},
        {"gyro", {{"columns", {"gz", "gy", "gx"}}, {"unit", "rad/s"}}},
        {"mag", {{"columns", {"mx", "my", "mz"}}, {"unit", "normalised"}, {"normalised_field_ut", 50.0}}},
        {"pressure", {{"column", "p"}, {"unit", "hPa"}}},
    };
    std::unique_ptr<RowReader> rows = open_with_column_map(input, map, builder, log);
    log.axes = "Xsens sensor frame x, y, z of the original export (the file's x/z swap undone), not levelled";
    // The note follows the rows' own notes, as it did when the file was read whole.
    return std::make_unique<NoteAtEnd>(
        std::move(rows), builder,
        "converted Xsens export: accelerometer in g of 9.70 m/s^2 (the author's divisor), columns x/z "
        "swapped back; magnetometer normalised, scaled by a nominal 50 uT; pressure in hPa");
}

}  // namespace pednav::io::detail
