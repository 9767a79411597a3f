// SPDX-License-Identifier: Apache-2.0
#include "log_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace pednav::io::detail {

namespace {

template <typename T>
void init_header(T& record, pn_record_type_t type, int64_t t_ns) {
    record.header.struct_size = sizeof(T);
    record.header.type = type;
    record.header.t_ns = t_ns;
    record.header.source_id = 0;
    record.header.flags = 0;
}

std::string fmt(const char* format, double a, double b = 0.0, double c = 0.0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, a, b, c);
    return buffer;
}

double median_of(std::vector<double> v) {
    if (v.empty()) return 0.0;
    auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

std::vector<double> intervals_of(const std::vector<double>& t) {
    std::vector<double> dt;
    dt.reserve(t.size());
    for (size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
    return dt;
}

double quantile_of(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    auto k = v.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), k, v.end());
    return *k;
}

}  // namespace

const char* stream_name(StreamId s) {
    switch (s) {
        case stream_accel: return "accel";
        case stream_gyro: return "gyro";
        case stream_mag: return "mag";
        case stream_pressure: return "pressure";
        case stream_gnss: return "gnss";
        case stream_truth: return "truth";
        default: return "?";
    }
}

int64_t seconds_to_ns(double t_s) {
    // Saturates instead of overflowing; accept_time keeps such times out of a log.
    if (!(std::fabs(t_s) < kMaxTimeS)) return t_s < 0 ? INT64_MIN : INT64_MAX;
    return static_cast<int64_t>(std::llround(t_s * 1e9));
}

LogBuilder::LogBuilder(SensorLog& log, const ReadOptions& options) : log_(log), options_(options) {}

void LogBuilder::note(const std::string& text) { log_.notes.push_back(text); }

void LogBuilder::issue(size_t line, const std::string& message) {
    if (log_.issues.size() < options_.max_issues) {
        log_.issues.push_back({line, context_.empty() ? message : context_ + ": " + message});
    } else {
        ++log_.issues_not_listed;
    }
}

void LogBuilder::bad_row(size_t line, const std::string& message, unsigned streams, const char* unit) {
    for (int s = 0; s < stream_count; ++s) {
        if (streams & (1u << s)) ++bad_[s];
    }
    issue(line, std::string(unit) + " skipped: " + message);
}

bool LogBuilder::accept_time(Clock& clock, size_t line, double t_s, unsigned streams) {
    if (!(std::fabs(t_s) < kMaxTimeS)) {
        bad_row(line,
                fmt("time %.6g s is beyond the +-%.3g s a nanosecond clock holds (a Unix time in ms, us or ns "
                    "read as seconds?)",
                    t_s, kMaxTimeS) +
                    (clock.name.empty() ? std::string() : " in " + clock.name),
                streams);
        return false;
    }
    const int64_t t_ns = seconds_to_ns(t_s);
    if (clock.has_last) {
        if (t_ns < clock.last_t_ns) {
            bad_row(line,
                    fmt("time goes backwards (%.9g s after %.9g s)", t_s,
                        static_cast<double>(clock.last_t_ns) * 1e-9) +
                        (clock.name.empty() ? std::string() : " in " + clock.name),
                    streams);
            return false;
        }
        if (t_ns == clock.last_t_ns) {
            auto& d = duplicates_[clock.name];
            if (d.count == 0) d.first_line = line;
            ++d.count;
            return false;
        }
    }
    clock.has_last = true;
    clock.last_t_ns = t_ns;
    return true;
}

void LogBuilder::add_imu(size_t line, double t_s, const double a[3], const double g[3]) {
    pn_imu_t r{};
    init_header(r, PN_REC_IMU, seconds_to_ns(t_s));
    for (int i = 0; i < 3; ++i) {
        r.accel_mps2[i] = a[i];
        r.gyro_radps[i] = g[i];
    }
    log_.imu.push_back(r);
    for (StreamId s : {stream_accel, stream_gyro}) {
        times_[s].push_back(t_s);
        lines_[s].push_back(line);
    }
}

void LogBuilder::add_accel(size_t line, double t_s, const double a[3]) {
    separate_imu_ = true;
    accel_raw_.push_back({seconds_to_ns(t_s), {a[0], a[1], a[2]}});
    times_[stream_accel].push_back(t_s);
    lines_[stream_accel].push_back(line);
    stream_context_[stream_accel] = context_;
}

void LogBuilder::add_gyro(size_t line, double t_s, const double g[3]) {
    separate_imu_ = true;
    gyro_raw_.push_back({seconds_to_ns(t_s), {g[0], g[1], g[2]}});
    times_[stream_gyro].push_back(t_s);
    lines_[stream_gyro].push_back(line);
    stream_context_[stream_gyro] = context_;
}

void LogBuilder::add_mag(size_t line, double t_s, const double m[3]) {
    pn_mag_t r{};
    init_header(r, PN_REC_MAG, seconds_to_ns(t_s));
    for (int i = 0; i < 3; ++i) r.mag_ut[i] = m[i];
    log_.mag.push_back(r);
    times_[stream_mag].push_back(t_s);
    lines_[stream_mag].push_back(line);
}

void LogBuilder::add_baro(size_t line, double t_s, double p_pa, double temp_c) {
    if (!(p_pa > 0.0)) {  // the engine refuses such records one by one: one summary issue at finish
        if (nonpositive_pressure_.count == 0) nonpositive_pressure_.first_line = line;
        ++nonpositive_pressure_.count;
        ++bad_[stream_pressure];
        return;
    }
    pn_baro_t r{};
    init_header(r, PN_REC_BARO, seconds_to_ns(t_s));
    r.pressure_pa = p_pa;
    r.temperature_c = temp_c;
    log_.baro.push_back(r);
    times_[stream_pressure].push_back(t_s);
    lines_[stream_pressure].push_back(line);
}

void LogBuilder::add_gnss(size_t line, double t_s, pn_gnss_t fix) {
    const uint32_t flags = fix.header.flags;
    init_header(fix, PN_REC_GNSS, seconds_to_ns(t_s));
    fix.header.flags = flags;
    log_.gnss.push_back(fix);
    times_[stream_gnss].push_back(t_s);
    lines_[stream_gnss].push_back(line);
}

void LogBuilder::add_truth(size_t line, const TruthPoint& point) {
    log_.truth.push_back(point);
    times_[stream_truth].push_back(point.t_s);
    lines_[stream_truth].push_back(line);
}

void LogBuilder::set_units(StreamId stream, const std::string& found, const std::string& converted) {
    units_found_[stream] = found;
    units_converted_[stream] = converted;
}

void LogBuilder::pair_accel_gyro() {
    if (!separate_imu_) return;
    size_t outside = 0;
    size_t j = 0;
    for (const auto& a : accel_raw_) {
        if (gyro_raw_.empty() || a.t_ns < gyro_raw_.front().t_ns || a.t_ns > gyro_raw_.back().t_ns) {
            ++outside;
            continue;
        }
        while (j + 1 < gyro_raw_.size() && gyro_raw_[j + 1].t_ns <= a.t_ns) ++j;
        const Raw3& g0 = gyro_raw_[j];
        const Raw3& g1 = (j + 1 < gyro_raw_.size()) ? gyro_raw_[j + 1] : g0;
        double w = 0.0;
        if (g1.t_ns > g0.t_ns)
            w = static_cast<double>(a.t_ns - g0.t_ns) / static_cast<double>(g1.t_ns - g0.t_ns);
        pn_imu_t r{};
        init_header(r, PN_REC_IMU, a.t_ns);
        for (int i = 0; i < 3; ++i) {
            r.accel_mps2[i] = a.v[i];
            r.gyro_radps[i] = g0.v[i] + w * (g1.v[i] - g0.v[i]);
        }
        log_.imu.push_back(r);
    }
    char text[200];
    std::snprintf(
        text, sizeof text,
        "accelerometer and gyroscope paired on the accelerometer times (gyroscope interpolated "
        "linearly): %zu IMU records; %zu accelerometer samples outside the gyroscope's time span dropped",
        log_.imu.size(), outside);
    note(text);
}

double LogBuilder::gap_threshold_s(double median_dt_s) const {
    // A gap is an interval longer than gap_s and than 2.5 of the stream's own
    // median intervals: routine 1 Hz GNSS or barometer jitter is no gap.
    return std::max(options_.gap_s, 2.5 * median_dt_s);
}

void LogBuilder::report_gaps(StreamId stream, const char* label) {
    context_ = stream_context_[stream];
    const auto& t = times_[stream];
    const std::vector<double> dt = intervals_of(t);
    const double median_dt = median_of(dt);
    const double gap_s = gap_threshold_s(median_dt);
    for (size_t i = 1; i < t.size(); ++i) {
        const double dt = t[i] - t[i - 1];
        if (dt > gap_s) {
            issue(lines_[stream][i],
                  fmt("gap of %.3f s in ", dt) + label + fmt(" (from t=%.3f s to t=%.3f s)", t[i - 1], t[i]));
        }
    }
    // Bursts: samples closer than a quarter of the median interval (a logger
    // flushing a buffer, a second source on the clock), one issue per stream.
    size_t burst = 0, first = 0, last = 0;
    double min_dt = median_dt;
    for (size_t i = 1; i < t.size(); ++i) {
        if (t[i] - t[i - 1] < 0.25 * median_dt) {
            if (burst++ == 0) first = lines_[stream][i];
            last = lines_[stream][i];
            min_dt = std::min(min_dt, t[i] - t[i - 1]);
        }
    }
    if (burst > 0) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "burst: %zu samples of %s closer than a quarter of the median interval %.4g s (lines "
                      "%zu-%zu, down to %.3g s apart: %.0f Hz)",
                      burst, label, median_dt, first, last, min_dt, min_dt > 0 ? 1.0 / min_dt : 0.0);
        issue(first, text);
    }
}

void LogBuilder::check_units() {
    if (!log_.imu.empty()) {
        std::vector<double> a_norm, w_norm;
        a_norm.reserve(log_.imu.size());
        w_norm.reserve(log_.imu.size());
        for (const auto& r : log_.imu) {
            a_norm.push_back(std::hypot(r.accel_mps2[0], r.accel_mps2[1], r.accel_mps2[2]));
            w_norm.push_back(std::hypot(r.gyro_radps[0], r.gyro_radps[1], r.gyro_radps[2]));
        }
        const double a_med = median_of(a_norm);
        if (a_med > 0.5 && a_med < 1.5) {
            issue(
                0,
                fmt("unit check: accelerometer magnitude median %.3f: gravity reads ~1, the values look like "
                    "g, "
                    "not m/s^2; not converted (the format does not say g: use a column map with unit \"g\")",
                    a_med));
        } else if (a_med > 30.0) {
            issue(
                0,
                fmt("unit check: accelerometer magnitude median %.3f m/s^2 is far above gravity: wrong unit?",
                    a_med));
        } else if (a_med < 0.5) {
            issue(0, fmt("unit check: accelerometer magnitude median %.3f m/s^2: no gravity in the signal "
                         "(linear acceleration?) or wrong unit",
                         a_med));
        }
        const double w_p99 = quantile_of(w_norm, 0.99);
        if (w_p99 > 25.0) {
            issue(0, fmt("unit check: gyroscope 99th percentile %.1f rad/s is implausible for a walk: the "
                         "values look "
                         "like deg/s; not converted (use a column map with unit \"deg/s\")",
                         w_p99));
        }
    }
    if (!log_.mag.empty()) {
        std::vector<double> m;
        for (const auto& r : log_.mag) m.push_back(std::hypot(r.mag_ut[0], r.mag_ut[1], r.mag_ut[2]));
        const double m_med = median_of(m);
        if (m_med < 5.0) {
            issue(0, fmt("unit check: magnetometer magnitude median %.3f uT is far below the Earth's field "
                         "(25-65 uT): "
                         "gauss or normalised units?",
                         m_med));
        } else if (m_med > 200.0) {
            issue(0, fmt("unit check: magnetometer magnitude median %.1f uT is far above the Earth's field: "
                         "nT or mG?",
                         m_med));
        }
    }
    if (!log_.baro.empty()) {
        std::vector<double> p;
        for (const auto& r : log_.baro) p.push_back(r.pressure_pa);
        const double p_med = median_of(p);
        if (p_med < 30000.0 || p_med > 110000.0) {
            issue(0,
                  fmt("unit check: pressure median %.3f Pa is not an atmospheric pressure in Pa: hPa or kPa?",
                      p_med));
        }
    }
}

void LogBuilder::finish() {
    context_.clear();
    pair_accel_gyro();
    if (log_.imu.empty() && imu_required_) {
        std::string reason = "no accelerometer and gyroscope sample could be read";
        if (!log_.issues.empty()) {
            reason += " (first problem: line " + std::to_string(log_.issues.front().line) + ": " +
                      log_.issues.front().message + ")";
        }
        throw ReadError(log_.path, 0, reason);
    }
    for (const auto& [name, d] : duplicates_) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "%zu samples with a repeated timestamp dropped%s%s (first at line %zu)", d.count,
                      name.empty() ? "" : " in ", name.c_str(), d.first_line);
        issue(d.first_line, text);
        note(text);
    }
    if (nonpositive_pressure_.count > 0) {
        char text[200];
        std::snprintf(text, sizeof text, "%zu pressure samples not positive dropped (first at line %zu)",
                      nonpositive_pressure_.count, nonpositive_pressure_.first_line);
        issue(nonpositive_pressure_.first_line, text);
    }
    if (separate_imu_) {
        report_gaps(stream_accel, "accel");
        report_gaps(stream_gyro, "gyro");
    } else {
        report_gaps(stream_accel, "accel/gyro");
    }
    report_gaps(stream_mag, "mag");
    report_gaps(stream_pressure, "pressure");
    report_gaps(stream_gnss, "gnss");
    context_.clear();
    check_units();

    log_.streams.clear();
    for (int s = 0; s < stream_count; ++s) {
        const auto id = static_cast<StreamId>(s);
        const auto& t = times_[s];
        if (t.empty() && units_found_[s].empty() && bad_[s] == 0) continue;
        StreamInfo info;
        info.name = stream_name(id);
        info.count = t.size();
        info.units_found = units_found_[s];
        info.units_converted = units_converted_[s];
        info.bad_rows = bad_[s];
        if (!t.empty()) {
            info.t_first_s = t.front();
            info.t_last_s = t.back();
        }
        if (t.size() >= 2) {
            info.duration_s = t.back() - t.front();
            if (info.duration_s > 0) info.rate_hz = static_cast<double>(t.size() - 1) / info.duration_s;
            const double dt_median = median_of(intervals_of(t));
            if (dt_median > 0) info.median_rate_hz = 1.0 / dt_median;
            // Truth points are sparse by nature: no gap count for them.
            if (id != stream_truth) {
                const double gap_s = gap_threshold_s(dt_median);
                for (size_t i = 1; i < t.size(); ++i) {
                    if (t[i] - t[i - 1] > gap_s) ++info.gaps;
                }
            }
        }
        log_.streams.push_back(info);
    }
}

}  // namespace pednav::io::detail
