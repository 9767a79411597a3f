// SPDX-License-Identifier: Apache-2.0
// senslogs two-file Android logs (humolire-phone): accelerometer-*.txt and
// gyroscope-*.txt side by side. Six header lines (the file's own name, a blank,
// the unit sentence, a link, a blank, the column names), then space-separated
// "elapsed-time-system elapsed-time-sensor x y z". Time: elapsed-time-sensor
// (s since the recording started). The gyroscope is interpolated at the
// accelerometer times. Axes: see android_axes.hpp.
#include "android_axes.hpp"
#include "formats.hpp"
#include "table_reader.hpp"

namespace pednav::io::detail {

namespace {

constexpr const char* kColumns = "elapsed-time-system elapsed-time-sensor x y z";

size_t header_index(const TextFile& file) {
    const size_t limit = std::min<size_t>(file.lines.size(), 10);
    for (size_t i = 0; i < limit; ++i) {
        if (trim(file.lines[i]) == kColumns) return i;
    }
    return std::string::npos;
}

std::string base_name(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string dir_name(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

// Replaces the first `from` in the file name by `to`.
std::string sibling(const std::string& path, const std::string& from, const std::string& to) {
    std::string name = base_name(path);
    const size_t at = name.find(from);
    if (at == std::string::npos) return "";
    name.replace(at, from.size(), to);
    return dir_name(path) + "/" + name;
}

void read_stream(const TextFile& file, bool accel, LogBuilder& builder) {
    const size_t header = header_index(file);
    if (header == std::string::npos)
        throw ReadError(file.path, 0, "no 'elapsed-time-system ...' header line");
    const std::string name = base_name(file.path);
    const unsigned bits = stream_bit(accel ? stream_accel : stream_gyro);
    builder.set_context(name);
    Clock clock(name);
    std::vector<std::string_view> fields;
    const char* columns[5] = {"elapsed-time-system", "elapsed-time-sensor", "x", "y", "z"};
    for (size_t index = header + 1; index < file.lines.size(); ++index) {
        const size_t line_no = index + 1;
        const std::string_view line = trim(file.lines[index]);
        if (line.empty()) continue;
        split_into(line, ' ', fields);
        if (fields.size() != 5) {
            builder.bad_row(line_no, fields.size() < 5 ? "truncated row" : "too many fields", bits);
            continue;
        }
        double v[5];
        bool ok = true;
        for (int k = 0; k < 5 && ok; ++k) {
            const NumberStatus status = parse_number(fields[static_cast<size_t>(k)], &v[k]);
            if (status != NumberStatus::ok) {
                builder.bad_row(
                    line_no, describe_bad_number(status, fields[static_cast<size_t>(k)], columns[k]), bits);
                ok = false;
            }
        }
        if (!ok || !builder.accept_time(clock, line_no, v[1], bits)) continue;
        double body[3];
        android_to_flu(&v[2], body);
        if (accel) {
            builder.add_accel(line_no, v[1], body);
        } else {
            builder.add_gyro(line_no, v[1], body);
        }
    }
    builder.set_context("");
}

}  // namespace

bool detect_humolire(const TextFile& file) {
    if (header_index(file) == std::string::npos || file.lines.empty()) return false;
    const std::string first = to_lower(trim(file.lines[0]));
    return starts_with(first, "accelerometer") || starts_with(first, "gyroscope");
}

void read_humolire(const TextFile& file, const ReadOptions&, LogBuilder& builder, SensorLog& log) {
    const std::string first = to_lower(trim(file.lines[0]));
    const bool given_accel = starts_with(first, "accelerometer");
    const std::string other_path = given_accel ? sibling(file.path, "accelerometer", "gyroscope")
                                               : sibling(file.path, "gyroscope", "accelerometer");
    if (other_path.empty()) {
        throw ReadError(file.path, 0,
                        "two-file recording: cannot derive the name of the other file (expected the words "
                        "'accelerometer' and 'gyroscope' in the file names)");
    }
    TextFile other;
    try {
        other = load_text_file(other_path);
    } catch (const ReadError& e) {
        throw ReadError(file.path, 0,
                        std::string("two-file recording: the ") +
                            (given_accel ? "gyroscope" : "accelerometer") + " file " + other_path + ": " +
                            e.reason());
    }
    const TextFile& accel_file = given_accel ? file : other;
    const TextFile& gyro_file = given_accel ? other : file;
    // The unit sentence of each file (line 3) must say what the engine assumes.
    const std::string accel_units = accel_file.lines.size() > 2 ? std::string(trim(accel_file.lines[2])) : "";
    const std::string gyro_units = gyro_file.lines.size() > 2 ? std::string(trim(gyro_file.lines[2])) : "";
    if (accel_units.find("m/s^2") == std::string::npos) {
        builder.issue(3, base_name(accel_file.path) + ": unit line does not say m/s^2 ('" + accel_units +
                             "'); read as m/s^2");
    }
    if (gyro_units.find("radians/second") == std::string::npos &&
        gyro_units.find("rad/s") == std::string::npos) {
        builder.issue(3, base_name(gyro_file.path) + ": unit line does not say radians/second ('" +
                             gyro_units + "'); read as rad/s");
    }
    builder.set_units(stream_accel, "m/s^2", "m/s^2");
    builder.set_units(stream_gyro, "rad/s", "rad/s");
    read_stream(accel_file, true, builder);
    read_stream(gyro_file, false, builder);
    log.axes = kAndroidAxesText;
    builder.note("two files: " + accel_file.path + " and " + gyro_file.path +
                 "; time from elapsed-time-sensor");
}

}  // namespace pednav::io::detail
