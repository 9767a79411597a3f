// SPDX-License-Identifier: Apache-2.0
// LogBuilder::finish and the summaries it makes of the whole file once it has
// been read: repeated times, gaps and bursts per stream, unit checks, the
// streams' rates. The samples are read back from the SpillVectors.
#include <algorithm>
#include <cstdio>

#include "log_builder.hpp"
#include "order_statistic.hpp"

namespace pednav::io::detail {

namespace {

std::string fmt(const char* format, double a, double b = 0.0, double c = 0.0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, format, a, b, c);
    return buffer;
}

// The k-th smallest of a SpillVector of doubles.
double kth_of(const SpillVector<double>& v, size_t k) {
    return kth_smallest(v.size(), k, [&](auto&& f) { v.for_each(f); });
}

}  // namespace

double LogBuilder::gap_threshold_s(double median_dt_s) const {
    // A gap is an interval longer than gap_s and than 2.5 of the stream's own
    // median intervals: routine 1 Hz GNSS or barometer jitter is no gap.
    return std::max(options_.gap_s, 2.5 * median_dt_s);
}

double LogBuilder::median_interval_s(StreamId stream) {
    const StreamId store = imu_rows_ && stream == stream_gyro ? stream_accel : stream;
    Intervals& known = intervals_[store];
    if (!known.known) {
        const SpillVector<TimeLine>& t = samples_[store];
        known.known = true;
        known.median_dt_s = t.size() < 2 ? 0.0 : kth_smallest(t.size() - 1, (t.size() - 1) / 2, [&](auto&& f) {
            bool first = true;
            double previous = 0.0;
            t.for_each([&](const TimeLine& s) {
                if (!first) f(s.t_s - previous);
                first = false;
                previous = s.t_s;
            });
        });
    }
    return known.median_dt_s;
}

void LogBuilder::report_gaps(StreamId stream, const char* label) {
    context_ = stream_context_[stream];
    const double median_dt = median_interval_s(stream);
    const double gap_s = gap_threshold_s(median_dt);
    // Gaps, one issue each; bursts: samples closer than a quarter of the median
    // interval (a logger flushing a buffer, a second source on the clock), one
    // issue per stream, after the gaps.
    size_t burst = 0, first = 0, last = 0;
    double min_dt = median_dt;
    bool started = false;
    double previous = 0.0;
    samples(stream).for_each([&](const TimeLine& s) {
        if (started) {
            const double dt = s.t_s - previous;
            if (dt > gap_s) {
                issue(static_cast<size_t>(s.line),
                      fmt("gap of %.3f s in ", dt) + label + fmt(" (from t=%.3f s to t=%.3f s)", previous, s.t_s));
            }
            if (dt < 0.25 * median_dt) {
                if (burst++ == 0) first = static_cast<size_t>(s.line);
                last = static_cast<size_t>(s.line);
                min_dt = std::min(min_dt, dt);
            }
        }
        started = true;
        previous = s.t_s;
    });
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
    if (log_.records.imu > 0) {
        const double a_med = kth_of(accel_norm_, accel_norm_.size() / 2);
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
        const size_t p99 = static_cast<size_t>(0.99 * static_cast<double>(gyro_norm_.size() - 1));
        const double w_p99 = kth_of(gyro_norm_, p99);
        if (w_p99 > 25.0) {
            issue(0, fmt("unit check: gyroscope 99th percentile %.1f rad/s is implausible for a walk: the "
                         "values look "
                         "like deg/s; not converted (use a column map with unit \"deg/s\")",
                         w_p99));
        }
    }
    if (log_.records.mag > 0) {
        const double m_med = kth_of(mag_norm_, mag_norm_.size() / 2);
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
    if (log_.records.baro > 0) {
        const double p_med = kth_of(pressure_, pressure_.size() / 2);
        if (p_med < 30000.0 || p_med > 110000.0) {
            issue(0,
                  fmt("unit check: pressure median %.3f Pa is not an atmospheric pressure in Pa: hPa or kPa?",
                      p_med));
        }
    }
}

void LogBuilder::finish() {
    context_.clear();
    gyro_ended_ = true;
    pair_accel_gyro();
    accel_ended_ = true;
    merge_channels();
    if (separate_imu_) {
        char text[200];
        std::snprintf(
            text, sizeof text,
            "accelerometer and gyroscope paired on the accelerometer times (gyroscope interpolated "
            "linearly): %zu IMU records; %zu accelerometer samples outside the gyroscope's time span dropped",
            paired_, outside_);
        note(text);
    }
    if (log_.records.imu == 0 && imu_required_) {
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
        const SpillVector<TimeLine>& t = samples(id);
        if (t.empty() && units_found_[s].empty() && bad_[s] == 0) continue;
        StreamInfo info;
        info.name = stream_name(id);
        info.count = t.size();
        info.units_found = units_found_[s];
        info.units_converted = units_converted_[s];
        info.bad_rows = bad_[s];
        if (!t.empty()) {
            info.t_first_s = t.front().t_s;
            info.t_last_s = t.back().t_s;
        }
        if (t.size() >= 2) {
            info.duration_s = info.t_last_s - info.t_first_s;
            if (info.duration_s > 0) info.rate_hz = static_cast<double>(t.size() - 1) / info.duration_s;
            const double dt_median = median_interval_s(id);
            if (dt_median > 0) info.median_rate_hz = 1.0 / dt_median;
            // Truth points are sparse by nature: no gap count for them.
            if (id != stream_truth) {
                const double gap_s = gap_threshold_s(dt_median);
                bool started = false;
                double previous = 0.0;
                t.for_each([&](const TimeLine& sample) {
                    if (started && sample.t_s - previous > gap_s) ++info.gaps;
                    started = true;
                    previous = sample.t_s;
                });
            }
        }
        log_.streams.push_back(info);
    }
}

}  // namespace pednav::io::detail
