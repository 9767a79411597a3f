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

LogBuilder::LogBuilder(SensorLog& log, const ReadOptions& options, RecordSink* sink)
    : log_(log), own_sink_(sink == nullptr ? new VectorSink(log) : nullptr),
      sink_(sink == nullptr ? own_sink_.get() : sink), options_(options) {}

void LogBuilder::note(const std::string& text) { log_.notes.push_back(text); }

void LogBuilder::issue(size_t line, const std::string& message) {
    std::vector<ReadIssue>& list = channel_ == 0 ? log_.issues : channel_issues_[channel_];
    if (list.size() < options_.max_issues) {
        list.push_back({line, context_.empty() ? message : context_ + ": " + message});
    } else {
        ++(channel_ == 0 ? log_.issues_not_listed : channel_not_listed_[channel_]);
    }
}

void LogBuilder::merge_channels() {
    channel_ = 0;
    for (int c = 1; c < kChannels; ++c) {
        for (auto& i : channel_issues_[c]) {
            if (log_.issues.size() < options_.max_issues)
                log_.issues.push_back(std::move(i));
            else
                ++log_.issues_not_listed;
        }
        log_.issues_not_listed += channel_not_listed_[c];
        channel_issues_[c].clear();
        channel_not_listed_[c] = 0;
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

bool LogBuilder::placeable(pn_record_type_t type, int64_t t_ns, size_t line, StreamId stream) {
    if (sink_->placeable(type, t_ns)) return true;
    char text[240];
    std::snprintf(text, sizeof text,
                  "%s sample at t=%.9g s is earlier than samples of the other streams already passed on: the "
                  "stream lags further behind them in the file than the merge window holds",
                  stream_name(stream), static_cast<double>(t_ns) * 1e-9);
    bad_row(line, text, stream_bit(stream));
    return false;
}

void LogBuilder::emit(const InputRecord& record) {
    RecordCounts& c = log_.records;
    switch (record.header.type) {
        case PN_REC_IMU:
            if (c.imu++ == 0) c.imu_first_t_ns = record.header.t_ns;
            accel_norm_.push_back(std::hypot(record.imu.accel_mps2[0], record.imu.accel_mps2[1], record.imu.accel_mps2[2]));
            gyro_norm_.push_back(std::hypot(record.imu.gyro_radps[0], record.imu.gyro_radps[1], record.imu.gyro_radps[2]));
            break;
        case PN_REC_MAG:
            ++c.mag;
            mag_norm_.push_back(std::hypot(record.mag.mag_ut[0], record.mag.mag_ut[1], record.mag.mag_ut[2]));
            break;
        case PN_REC_BARO:
            ++c.baro;
            pressure_.push_back(record.baro.pressure_pa);
            break;
        case PN_REC_GNSS: ++c.gnss; break;
        default: break;
    }
    sink_->add(record);
}

void LogBuilder::add_sample(StreamId stream, size_t line, double t_s) {
    samples_[stream].push_back({t_s, static_cast<uint64_t>(line)});
}

SpillVector<LogBuilder::TimeLine>& LogBuilder::samples(StreamId stream) {
    return samples_[imu_rows_ && stream == stream_gyro ? stream_accel : stream];
}

void LogBuilder::add_imu(size_t line, double t_s, const double a[3], const double g[3]) {
    InputRecord r{};
    init_header(r.imu, PN_REC_IMU, seconds_to_ns(t_s));
    if (!placeable(PN_REC_IMU, r.header.t_ns, line, stream_accel)) return;
    for (int i = 0; i < 3; ++i) {
        r.imu.accel_mps2[i] = a[i];
        r.imu.gyro_radps[i] = g[i];
    }
    imu_rows_ = true;
    add_sample(stream_accel, line, t_s);
    emit(r);
}

void LogBuilder::add_accel(size_t line, double t_s, const double a[3]) {
    separate_imu_ = true;
    accel_raw_.push_back({seconds_to_ns(t_s), line, {a[0], a[1], a[2]}});
    last_accel_t_ns_ = accel_raw_.back().t_ns;
    add_sample(stream_accel, line, t_s);
    stream_context_[stream_accel] = context_;
    pair_accel_gyro();
}

void LogBuilder::add_gyro(size_t line, double t_s, const double g[3]) {
    separate_imu_ = true;
    const Raw3 raw{seconds_to_ns(t_s), line, {g[0], g[1], g[2]}};
    if (!have_first_gyro_) {
        have_first_gyro_ = true;
        first_gyro_t_ns_ = raw.t_ns;
    }
    gyro_raw_.push_back(raw);
    add_sample(stream_gyro, line, t_s);
    stream_context_[stream_gyro] = context_;
    pair_accel_gyro();
}

void LogBuilder::add_mag(size_t line, double t_s, const double m[3]) {
    InputRecord r{};
    init_header(r.mag, PN_REC_MAG, seconds_to_ns(t_s));
    if (!placeable(PN_REC_MAG, r.header.t_ns, line, stream_mag)) return;
    for (int i = 0; i < 3; ++i) r.mag.mag_ut[i] = m[i];
    add_sample(stream_mag, line, t_s);
    emit(r);
}

void LogBuilder::add_baro(size_t line, double t_s, double p_pa, double temp_c) {
    if (!(p_pa > 0.0)) {  // the engine refuses such records one by one: one summary issue at finish
        if (nonpositive_pressure_.count == 0) nonpositive_pressure_.first_line = line;
        ++nonpositive_pressure_.count;
        ++bad_[stream_pressure];
        return;
    }
    InputRecord r{};
    init_header(r.baro, PN_REC_BARO, seconds_to_ns(t_s));
    if (!placeable(PN_REC_BARO, r.header.t_ns, line, stream_pressure)) return;
    r.baro.pressure_pa = p_pa;
    r.baro.temperature_c = temp_c;
    add_sample(stream_pressure, line, t_s);
    emit(r);
}

void LogBuilder::add_gnss(size_t line, double t_s, pn_gnss_t fix) {
    const uint32_t flags = fix.header.flags;
    init_header(fix, PN_REC_GNSS, seconds_to_ns(t_s));
    fix.header.flags = flags;
    if (!placeable(PN_REC_GNSS, fix.header.t_ns, line, stream_gnss)) return;
    InputRecord r{};
    r.gnss = fix;
    add_sample(stream_gnss, line, t_s);
    emit(r);
}

void LogBuilder::add_truth(size_t line, const TruthPoint& point) {
    log_.truth.push_back(point);
    add_sample(stream_truth, line, point.t_s);
}

void LogBuilder::set_units(StreamId stream, const std::string& found, const std::string& converted) {
    units_found_[stream] = found;
    units_converted_[stream] = converted;
}

void LogBuilder::end_of(StreamId stream) {
    if (stream == stream_accel) accel_ended_ = true;
    if (stream == stream_gyro) gyro_ended_ = true;
    pair_accel_gyro();
}

void LogBuilder::pair_accel_gyro() {
    const bool gyro_ended = gyro_ended_;
    while (!accel_raw_.empty()) {
        const Raw3& a = accel_raw_.front();
        if (!have_first_gyro_ && !gyro_ended) return;  // the gyroscope may still start before it
        if (!have_first_gyro_ || a.t_ns < first_gyro_t_ns_) {
            ++outside_;
            accel_raw_.pop_front();
            continue;
        }
        // gyro_raw_.front() is the last gyroscope sample at or before a; the one after it brackets a.
        while (gyro_raw_.size() >= 2 && gyro_raw_[1].t_ns <= a.t_ns) gyro_raw_.pop_front();
        const Raw3& g0 = gyro_raw_.front();
        const Raw3* g1 = gyro_raw_.size() >= 2 ? &gyro_raw_[1] : nullptr;
        if (g1 == nullptr) {
            if (!gyro_ended) return;  // the next gyroscope sample is not read yet
            if (a.t_ns > g0.t_ns) {    // after the gyroscope's last sample
                ++outside_;
                accel_raw_.pop_front();
                continue;
            }
            g1 = &g0;
        }
        double w = 0.0;
        if (g1->t_ns > g0.t_ns)
            w = static_cast<double>(a.t_ns - g0.t_ns) / static_cast<double>(g1->t_ns - g0.t_ns);
        InputRecord r{};
        init_header(r.imu, PN_REC_IMU, a.t_ns);
        for (int i = 0; i < 3; ++i) {
            r.imu.accel_mps2[i] = a.v[i];
            r.imu.gyro_radps[i] = g0.v[i] + w * (g1->v[i] - g0.v[i]);
        }
        if (placeable(PN_REC_IMU, a.t_ns, a.line, stream_accel)) {
            ++paired_;
            emit(r);
        }
        accel_raw_.pop_front();
    }
    // Gyroscope samples no later accelerometer sample can need.
    if (accel_ended_) {
        gyro_raw_.clear();
    } else if (!samples_[stream_accel].empty()) {  // a later accelerometer sample comes after the last
        while (gyro_raw_.size() >= 2 && gyro_raw_[1].t_ns <= last_accel_t_ns_) gyro_raw_.pop_front();
    }
}

}  // namespace pednav::io::detail
