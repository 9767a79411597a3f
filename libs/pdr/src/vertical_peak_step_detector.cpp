// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr/vertical_peak_step_detector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pednav::pdr {

namespace {
constexpr uint64_t kAltitudeRing = 1024;  // barometer readings kept for C3 (20 s at 50 Hz)

const VerticalPeakStepConfig& checked(const VerticalPeakStepConfig& c) {
    if (!(c.gravity_time_constant_s > 0)) throw std::invalid_argument("gravity_time_constant_s must be > 0");
    if (!(c.smoothing_window_s >= 0)) throw std::invalid_argument("smoothing_window_s must be >= 0");
    if (!(c.min_step_interval_s > 0)) throw std::invalid_argument("min_step_interval_s must be > 0");
    if (!(c.max_step_interval_s > c.min_step_interval_s))
        throw std::invalid_argument("max_step_interval_s must be above min_step_interval_s");
    if (!(c.accel_max_threshold_mps2 > c.accel_min_threshold_mps2))
        throw std::invalid_argument("accel_max_threshold_mps2 must be above accel_min_threshold_mps2");
    if (!(c.bout_accel_max_threshold_mps2 <= c.accel_max_threshold_mps2) ||
        !(c.bout_accel_min_threshold_mps2 >= c.accel_min_threshold_mps2) ||
        !(c.bout_accel_max_threshold_mps2 > c.bout_accel_min_threshold_mps2))
        throw std::invalid_argument(
            "bout_accel_max_threshold_mps2 must be at most accel_max_threshold_mps2 and above "
            "bout_accel_min_threshold_mps2, which must be at least accel_min_threshold_mps2");
    if (!(c.stairs_rise_min_m > 0) || !(c.baro_window_s > 0) || !(c.turn_rate_min_radps > 0))
        throw std::invalid_argument("stairs_rise_min_m, baro_window_s and turn_rate_min_radps must be > 0");
    return c;
}

int64_t ns_of(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }
}  // namespace

VerticalPeakStepDetector::VerticalPeakStepDetector(const VerticalPeakStepConfig& config, double max_rate_hz)
    : c_(checked(config)),
      vertical_(config.gravity_time_constant_s),
      smoother_(config.smoothing_window_s, max_rate_hz),
      peaks_(2.0 * config.min_step_interval_s, max_rate_hz),
      altimeter_(config.baro),
      yaw_ring_(signal::ring_size_for_window(config.smoothing_window_s + 2.0 * config.min_step_interval_s + 0.1,
                                             max_rate_hz)),
      yaw_mask_(yaw_ring_.size() - 1),
      min_since_candidate_(HUGE_VAL),
      alt_t_(kAltitudeRing),
      alt_m_(kAltitudeRing) {
    // A step at t is emitted at the latest when the candidate after it is
    // judged: at most max_step_interval_s later, plus the two half windows;
    // 50 ms cover the samples that must arrive past each window's edge.
    latency_ns_ = ns_of(c_.max_step_interval_s + 0.05) + smoother_.half_window_ns() + peaks_.half_window_ns();
}

void VerticalPeakStepDetector::reset() {
    smoother_.reset();
    peaks_.reset();
    altimeter_.reset();
    pushed_ = judged_ = 0;
    vertical_.reset();
    t_last_ns_ = 0;
    yaw_rad_ = 0;
    min_since_candidate_ = HUGE_VAL;
    bout_open_ = has_pending_ = false;
    steps_ = 0;
    alt_n_ = 0;
}

void VerticalPeakStepDetector::push_baro(int64_t t_ns, double pressure_pa) {
    altimeter_.push(t_ns, pressure_pa);
    if (!altimeter_.ready()) return;
    alt_t_[alt_n_ % kAltitudeRing] = t_ns;
    alt_m_[alt_n_ % kAltitudeRing] = altimeter_.altitude_m();
    ++alt_n_;
}

void VerticalPeakStepDetector::on_imu(int64_t t_ns, const double a[3], const double w[3]) {
    const double a_v = vertical_.push(t_ns, a);
    t_last_ns_ = t_ns;
    yaw_rad_ -= vertical_.along_vertical(w) * vertical_.dt_s();  // counter-clockwise about up is a heading decrease
    yaw_ring_[pushed_++ & yaw_mask_] = yaw_rad_;
    smoother_.push(t_ns, a_v, [this](int64_t t, double v) { on_filtered(t, v); });
}

void VerticalPeakStepDetector::on_flush() {
    smoother_.flush([this](int64_t t, double v) { on_filtered(t, v); });
    peaks_.flush([this](int64_t t, double v, bool peak) { on_judged(t, v, peak); });
    if (bout_open_) {
        // The walk ends in a step: close the bout at the last sample.
        VerticalStepEvent e;
        e.t_start_ns = last_.t_ns;
        e.t_ns = std::max(t_last_ns_, last_.t_ns);
        e.mode = MotionMode::standing;
        emit(e);
        bout_open_ = false;
    }
    has_pending_ = false;
}

void VerticalPeakStepDetector::on_filtered(int64_t t_ns, double a_v) {
    peaks_.push(t_ns, a_v, [this](int64_t t, double v, bool peak) { on_judged(t, v, peak); });
}

void VerticalPeakStepDetector::on_judged(int64_t t_ns, double a_v, bool peak) {
    const double yaw = yaw_ring_[judged_++ & yaw_mask_];
    min_since_candidate_ = std::min(min_since_candidate_, a_v);
    const int64_t max_ns = ns_of(c_.max_step_interval_s);
    if (bout_open_ && t_ns - last_.t_ns > max_ns) {
        VerticalStepEvent e;  // Table 1, C1 = C2 = 0: the walker stands
        e.t_start_ns = last_.t_ns;
        e.t_ns = last_.t_ns + max_ns;
        e.mode = MotionMode::standing;
        emit(e);
        bout_open_ = false;
    }
    if (has_pending_ && t_ns - pending_.t_ns > max_ns) has_pending_ = false;  // an isolated peak
    // C1, with the weaker thresholds while a bout is open (hysteresis).
    const double max_threshold = bout_open_ ? c_.bout_accel_max_threshold_mps2 : c_.accel_max_threshold_mps2;
    const double min_threshold = bout_open_ ? c_.bout_accel_min_threshold_mps2 : c_.accel_min_threshold_mps2;
    if (!peak || !(a_v > max_threshold)) return;
    const Candidate cand{t_ns, a_v, min_since_candidate_, yaw};
    min_since_candidate_ = HUGE_VAL;
    if (cand.min_mps2 < min_threshold) on_candidate(cand);
}

void VerticalPeakStepDetector::on_candidate(const Candidate& c) {
    const int64_t max_ns = ns_of(c_.max_step_interval_s);
    if (bout_open_ && c.t_ns - last_.t_ns <= max_ns) {  // C2 with the bout's last step
        emit_step(c, last_.t_ns, last_.yaw_rad);
    } else if (has_pending_ && c.t_ns - pending_.t_ns <= max_ns) {
        // C2 confirms a bout: its first step (one period long, its yaw
        // change extrapolated from the second), then this one.
        const Candidate first = pending_;
        has_pending_ = false;
        const int64_t period = c.t_ns - first.t_ns;
        emit_step(first, first.t_ns - period, 2.0 * first.yaw_rad - c.yaw_rad);
        bout_open_ = true;
        emit_step(c, first.t_ns, first.yaw_rad);
    } else {
        pending_ = c;
        has_pending_ = true;
    }
}

void VerticalPeakStepDetector::emit_step(const Candidate& c, int64_t t_start_ns, double yaw_start_rad) {
    VerticalStepEvent e;
    e.t_start_ns = t_start_ns;
    e.t_ns = c.t_ns;
    e.accel_max_mps2 = c.max_mps2;
    e.accel_min_mps2 = c.min_mps2;
    const double duration_s = static_cast<double>(c.t_ns - t_start_ns) * 1e-9;
    e.frequency_hz = duration_s > 0 ? 1.0 / duration_s : 0.0;
    e.heading_change_rad = c.yaw_rad - yaw_start_rad;
    e.altitude_change_m = altitude_change_m(c.t_ns, duration_s);
    // C4 over this step and the one before it when both are in the bout.
    double turn_rate_radps = duration_s > 0 ? std::abs(e.heading_change_rad) / duration_s : 0.0;
    if (bout_open_ && last_start_ns_ < t_start_ns && t_start_ns == last_.t_ns) {
        const double span_s = static_cast<double>(c.t_ns - last_start_ns_) * 1e-9;
        if (span_s > 0) turn_rate_radps = std::abs(c.yaw_rad - last_start_yaw_) / span_s;
    }
    if (e.altitude_change_m > c_.stairs_rise_min_m) e.mode = MotionMode::upstairs;
    else if (e.altitude_change_m < -c_.stairs_rise_min_m) e.mode = MotionMode::downstairs;
    else if (turn_rate_radps > c_.turn_rate_min_radps) e.mode = MotionMode::turning;
    else e.mode = MotionMode::straight;
    last_start_ns_ = t_start_ns;
    last_start_yaw_ = yaw_start_rad;
    last_ = c;
    ++steps_;
    emit(e);
}

void VerticalPeakStepDetector::emit(const VerticalStepEvent& e) {
    if (sink_) sink_(sink_user_, e);
}

double VerticalPeakStepDetector::altitude_at(int64_t t_ns) const {
    // The newest reading at or before t (the oldest kept when all are later).
    const uint64_t kept = std::min<uint64_t>(alt_n_, kAltitudeRing);
    for (uint64_t i = 0; i < kept; ++i) {
        const uint64_t k = (alt_n_ - 1 - i) % kAltitudeRing;
        if (alt_t_[k] <= t_ns || i + 1 == kept) return alt_m_[k];
    }
    return 0.0;
}

double VerticalPeakStepDetector::altitude_change_m(int64_t t_ns, double duration_s) const {
    if (alt_n_ < 2) return 0.0;
    const int64_t newest = alt_t_[(alt_n_ - 1) % kAltitudeRing];
    const int64_t oldest = alt_t_[(alt_n_ - std::min<uint64_t>(alt_n_, kAltitudeRing)) % kAltitudeRing];
    const int64_t half = ns_of(0.5 * c_.baro_window_s);
    const int64_t t0 = std::max(t_ns - half, oldest), t1 = std::min(t_ns + half, newest);
    if (t1 - t0 < half / 2) return 0.0;  // too little of the window
    const double rate_mps = (altitude_at(t1) - altitude_at(t0)) / (static_cast<double>(t1 - t0) * 1e-9);
    return rate_mps * duration_s;
}

}  // namespace pednav::pdr
