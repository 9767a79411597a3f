// SPDX-License-Identifier: Apache-2.0
// GNSS file detection and dispatch, use_gnss, parse_utc.
#include <cmath>
#include <cstdio>
#include <ctime>

#include "formats.hpp"
#include "gnss_formats.hpp"

namespace pednav::io {

namespace {

struct GnssReader {
    const char* name;
    const char* description;
    bool (*detect)(const detail::TextFile& file);
    void (*read)(const detail::TextFile& file, const GnssReadOptions& options, detail::LogBuilder& builder,
                 SensorLog& log);
};

const std::vector<GnssReader>& gnss_readers() {
    static const std::vector<GnssReader> readers = {
        {"nmea", "NMEA 0183 sentences (GGA, RMC, GSA, GST, VTG, ZDA) of any talker", detail::detect_nmea,
         detail::read_nmea},
        {"csv", "GNSS CSV t,lat,lon,alt,hacc,vacc,speed,course,sats in s, deg, m, m/s, deg", detail::detect_gnss_csv,
         detail::read_gnss_csv},
    };
    return readers;
}

const GnssReader* detect(const detail::TextFile& file) {
    for (const auto& r : gnss_readers()) {
        if (r.detect(file)) return &r;
    }
    return nullptr;
}

}  // namespace

std::vector<std::string> supported_gnss_formats() {
    std::vector<std::string> names;
    for (const auto& r : gnss_readers()) names.emplace_back(r.name);
    return names;
}

std::string detect_gnss_format(const std::string& path) {
    const detail::TextFile file = detail::load_text_file(path);
    const GnssReader* reader = detect(file);
    if (reader == nullptr) throw ReadError(path, 0, "not a GNSS file (neither NMEA sentences nor a t,lat,lon CSV)");
    return reader->name;
}

namespace {

// Consecutive fixes further apart than a pedestrian, or a car, could go:
// one issue for the file, with the first jump.
constexpr double kMaxGnssSpeed_mps = 50.0;

void report_jumps(SensorLog& log) {
    size_t jumps = 0;
    char first[200] = "";
    for (size_t i = 1; i < log.gnss.size(); ++i) {
        const pn_gnss_t& a = log.gnss[i - 1];
        const pn_gnss_t& b = log.gnss[i];
        const double dt_s = static_cast<double>(b.header.t_ns - a.header.t_ns) * 1e-9;
        const double north_m = (b.lat_deg - a.lat_deg) * 111320.0;
        const double east_m = (b.lon_deg - a.lon_deg) * 111320.0 * std::cos(a.lat_deg * 0.017453292519943295);
        const double d_m = std::hypot(north_m, east_m);
        if (dt_s > 0 && d_m / dt_s > kMaxGnssSpeed_mps) {
            if (jumps++ == 0)
                std::snprintf(first, sizeof first, "%.0f m in %.3g s at t=%.3f s", d_m, dt_s,
                              static_cast<double>(b.header.t_ns) * 1e-9);
        }
    }
    if (jumps > 0) {
        log.issues.push_back({0, "GNSS jumps: " + std::to_string(jumps) + " fixes lie faster than " +
                                     std::to_string(static_cast<int>(kMaxGnssSpeed_mps)) +
                                     " m/s from the one before (first: " + first + ")"});
    }
}

}  // namespace

SensorLog read_gnss_file(const std::string& path, const GnssReadOptions& options) {
    if (!(options.uere_m > 0.0 && options.uere_m < 1000.0))
        throw ReadError(path, 0, "the UERE must be within 0 .. 1000 m");
    const detail::TextFile file = detail::load_text_file(path);
    const bool automatic = options.format.empty() || options.format == "auto";
    const GnssReader* reader = nullptr;
    if (automatic) {
        reader = detect(file);
        if (reader == nullptr) {
            const size_t first = detail::first_content_line(file);
            const std::string head =
                first < file.lines.size() ? std::string(file.lines[first].substr(0, 80)) : std::string();
            throw ReadError(path, first + 1,
                            "unknown GNSS format (first line '" + head +
                                "'): expected NMEA sentences ($GPGGA,...) or a CSV header with t,lat,lon");
        }
    } else {
        for (const auto& r : gnss_readers())
            if (options.format == r.name) reader = &r;
        if (reader == nullptr)
            throw ReadError(path, 0, "unknown GNSS format name '" + options.format + "' (nmea or csv)");
    }
    SensorLog log;
    log.format = reader->name;
    log.path = path;
    ReadOptions ro;
    ro.gap_s = options.gap_s;
    ro.max_issues = options.max_issues;
    detail::LogBuilder builder(log, ro);
    builder.set_imu_required(false);
    builder.note(std::string("format: ") + reader->name + " (" + reader->description + ")" +
                 (automatic ? ", detected" : ", as requested"));
    reader->read(file, options, builder, log);
    builder.finish();
    report_jumps(log);
    if (log.gnss.empty()) {
        std::string reason = "no GNSS fix could be read";
        if (!log.issues.empty())
            reason += " (first problem: line " + std::to_string(log.issues.front().line) + ": " +
                      log.issues.front().message + ")";
        else
            reason += " (the receiver had no fix in the whole file)";
        throw ReadError(path, 0, reason);
    }
    return log;
}

void use_gnss(SensorLog& log, const SensorLog& gnss) {
    const size_t own = log.records.gnss;
    char before_imu[200] = "";
    if (log.records.imu > 0) {
        const int64_t t0_ns = log.records.imu_first_t_ns;
        size_t before = 0;
        for (const auto& g : gnss.gnss) before += g.header.t_ns < t0_ns ? 1 : 0;
        if (before > 0)
            std::snprintf(before_imu, sizeof before_imu, "; %zu of them before the first IMU sample (t = %.3f s)",
                          before, static_cast<double>(t0_ns) * 1e-9);
    }
    log.gnss = gnss.gnss;
    log.records.gnss = gnss.gnss.size();
    for (auto it = log.streams.begin(); it != log.streams.end();) {
        it = it->name == "gnss" ? log.streams.erase(it) : it + 1;
    }
    if (const StreamInfo* s = gnss.stream("gnss")) log.streams.push_back(*s);
    std::string note = "GNSS: " + std::to_string(gnss.gnss.size()) + " fixes from " + gnss.path + " (" +
                       gnss.format + ")";
    if (own > 0) note += ", in place of the " + std::to_string(own) + " GNSS records of the input";
    note += before_imu;
    log.notes.push_back(note);
    if (log.utc_ns_at_zero == 0) log.utc_ns_at_zero = gnss.utc_ns_at_zero;
}

bool parse_utc(const std::string& text, int64_t* utc_ns) {
    // Unix seconds: whole seconds and the fraction apart, exact to the nanosecond.
    double seconds = 0.0;
    if (parse_number(text, &seconds) == NumberStatus::ok) {
        if (!(seconds > 0.0 && seconds < 1e11)) return false;
        if (text.find_first_of("eE") != std::string::npos) {
            *utc_ns = static_cast<int64_t>(std::llround(seconds * 1e9));
            return true;
        }
        const size_t point = text.find('.');
        double whole = 0.0, fraction = 0.0;
        parse_number(std::string_view(text).substr(0, point), &whole);
        if (point != std::string::npos && point + 1 < text.size())
            parse_number("0" + text.substr(point), &fraction);
        *utc_ns = static_cast<int64_t>(whole) * 1000000000 + std::llround(fraction * 1e9);
        return true;
    }
    int year = 0, month = 0, day = 0, hour = 0, minute = 0, used = 0;
    if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%n", &year, &month, &day, &hour, &minute, &used) != 5 ||
        used == 0)
        return false;
    const std::string rest = text.substr(static_cast<size_t>(used));
    if (rest.empty() || rest.back() != 'Z') return false;
    double second = 0.0;
    if (parse_number(std::string_view(rest).substr(0, rest.size() - 1), &second) != NumberStatus::ok) return false;
    if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second < 0 || second >= 61)
        return false;
    std::tm tm{};
    tm.tm_year = year - 1900;
    tm.tm_mon = month - 1;
    tm.tm_mday = day;
    tm.tm_hour = hour;
    tm.tm_min = minute;
    const int64_t whole = static_cast<int64_t>(timegm(&tm));
    *utc_ns = whole * 1000000000 + static_cast<int64_t>(std::llround(second * 1e9));
    return true;
}

}  // namespace pednav::io
