// SPDX-License-Identifier: Apache-2.0
// Format detection and choice, merged_records, and the small public helpers.
#include <dirent.h>
#include <sys/stat.h>
#include <algorithm>

#include "formats.hpp"
#include "pednav_io/sensor_log.hpp"

namespace pednav::io {

namespace {

std::string make_message(const std::string& path, size_t line, const std::string& reason) {
    std::string text = path;
    if (line > 0) text += ":" + std::to_string(line);
    return text + ": " + reason;
}

bool is_directory(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// A folder holding a two-file recording: the path of its accelerometer file.
std::string resolve_folder(const std::string& path) {
    DIR* dir = opendir(path.c_str());
    if (dir == nullptr) throw ReadError(path, 0, "cannot open the folder");
    std::vector<std::string> candidates;
    while (dirent* entry = readdir(dir)) {
        const std::string name = entry->d_name;
        if (detail::starts_with(name, "accelerometer") && detail::ends_with(name, ".txt"))
            candidates.push_back(name);
    }
    closedir(dir);
    std::sort(candidates.begin(), candidates.end());
    if (candidates.empty()) {
        throw ReadError(path, 0,
                        "is a folder without a recording (expected accelerometer*.txt and gyroscope*.txt)");
    }
    // Prefer the calibrated file when both raw and calibrated exist.
    for (const auto& c : candidates) {
        if (c.find("calibrated") != std::string::npos && c.find("uncalibrated") == std::string::npos) {
            return std::string(path).append("/").append(c);
        }
    }
    return std::string(path).append("/").append(candidates.front());
}

const detail::FormatReader* find_reader(const std::string& name) {
    for (const auto& r : detail::format_readers()) {
        if (name == r.name) return &r;
    }
    return nullptr;
}

const detail::FormatReader* detect(const detail::TextFile& head) {
    for (const auto& r : detail::format_readers()) {
        if (r.detect != nullptr && r.detect(head)) return &r;
    }
    return nullptr;
}

}  // namespace

ReadError::ReadError(const std::string& path, size_t line, const std::string& reason)
    : std::runtime_error(make_message(path, line, reason)), path_(path), line_(line), reason_(reason) {}

const StreamInfo* SensorLog::stream(const std::string& name) const {
    for (const auto& s : streams) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

namespace detail {

size_t first_content_line(const TextFile& file) {
    for (size_t i = 0; i < file.lines.size(); ++i) {
        const std::string_view line = trim(file.lines[i]);
        if (line.empty() || line[0] == '#' || line[0] == '%' || starts_with(line, "//")) continue;
        return i;
    }
    return file.lines.size();
}

size_t header_line_index(const TextFile& file, const char* format) {
    const size_t index = first_content_line(file);
    if (index >= file.lines.size()) {
        throw ReadError(file.path, 0,
                        std::string("no header line for format ") + format +
                            ": the file holds only blank and comment lines");
    }
    return index;
}

const std::vector<FormatReader>& format_readers() {
    // Detection order: the most specific header first.
    static const std::vector<FormatReader> readers = {
        {"ipin-logfile", "IPIN competition logfile (ACCE;GYRO;MAGN;PRES;GNSS;POSI lines)", detect_ipin,
         open_ipin},
        {"humolire-senslogs", "senslogs two-file Android log (accelerometer/gyroscope .txt)", detect_humolire,
         open_humolire},
        {"microstrain-sensorconnect-a", "MicroStrain SensorConnect CSV, scaled* channels (g, rad/s, gauss)",
         detect_microstrain_a, open_microstrain},
        {"microstrain-sensorconnect-b",
         "MicroStrain SensorConnect CSV, estCompensated* channels (m/s^2, rad/s)", detect_microstrain_b,
         open_microstrain},
        {"xio-ngimu-csv", "x-io NGIMU / x-IMU CSV (\"Time (s)\", deg/s, g)", detect_xio_csv, open_xio_csv},
        {"xsens-mtw-tsv", "Xsens tab-separated export (PacketCounter, Acc_X, ...)", detect_xsens_mtw_tsv,
         open_xsens},
        {"xsens-mtmanager-csv", "Xsens MT Manager CSV export (PacketCounter, SampleTimeFine, Acc_X, ...)",
         detect_xsens_mtmanager_csv, open_xsens},
        {"xsens-converted-g-csv",
         "Xsens export converted to time,gx..,ax.. in g, p in hPa (biba mapmatching_run)",
         detect_biba_converted_csv, open_biba_converted_csv},
        {"pednav-csv", "canonical CSV t,ax,ay,az,gx,gy,gz[,mx,my,mz][,p] in s, m/s^2, rad/s, uT, Pa",
         detect_pednav_csv, open_pednav_csv},
        {"column-map", "any delimited file described by a column map (ReadOptions::column_map)", nullptr,
         open_column_map},
    };
    return readers;
}

}  // namespace detail

std::vector<std::string> supported_formats() {
    std::vector<std::string> names;
    for (const auto& r : detail::format_readers()) names.emplace_back(r.name);
    return names;
}

namespace detail {

std::string resolve_recording_path(const std::string& path) {
    return is_directory(path) ? resolve_folder(path) : path;
}

const FormatReader& choose_reader(const std::string& path, const TextFile& head, const ReadOptions& options) {
    const FormatReader* reader = nullptr;
    if (options.format.empty() || options.format == "auto") {
        if (options.column_map != nullptr) {
            reader = find_reader("column-map");
        } else {
            reader = detect(head);
            if (reader == nullptr) {
                const size_t first = first_content_line(head);
                const std::string text =
                    first < head.lines.size() ? std::string(head.lines[first].substr(0, 80)) : std::string();
                throw ReadError(path, first + 1,
                                "unknown format (first line '" + text +
                                    "'); name it with --format or describe it with a column map");
            }
        }
    } else {
        reader = find_reader(options.format);
        if (reader == nullptr) throw ReadError(path, 0, "unknown format name '" + options.format + "'");
    }
    return *reader;
}

}  // namespace detail

std::string detect_format(const std::string& path) {
    detail::InputFile input(detail::resolve_recording_path(path));
    const detail::FormatReader* reader = detect(input.head());
    if (reader == nullptr) throw ReadError(path, 0, "unknown format");
    return reader->name;
}

std::vector<const pn_record_header_t*> merged_records(const SensorLog& log) {
    return merged_records(log.imu, log.mag, log.baro, log.gnss);
}

std::vector<const pn_record_header_t*> merged_records(const std::vector<pn_imu_t>& imu,
                                                      const std::vector<pn_mag_t>& mag,
                                                      const std::vector<pn_baro_t>& baro,
                                                      const std::vector<pn_gnss_t>& gnss) {
    std::vector<const pn_record_header_t*> out;
    out.reserve(imu.size() + mag.size() + baro.size() + gnss.size());
    for (const auto& r : imu) out.push_back(&r.header);
    for (const auto& r : mag) out.push_back(&r.header);
    for (const auto& r : baro) out.push_back(&r.header);
    for (const auto& r : gnss) out.push_back(&r.header);
    // Each stream is already in time order and they were appended IMU, MAG,
    // BARO, GNSS: a stable sort on time keeps that order at equal t_ns.
    std::stable_sort(out.begin(), out.end(), [](const pn_record_header_t* a, const pn_record_header_t* b) {
        return a->t_ns < b->t_ns;
    });
    return out;
}

}  // namespace pednav::io
