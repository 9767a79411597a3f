// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr/peak_step_detector.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pednav::pdr {

namespace {

void require(bool ok, const char* field, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("peak step detector: ") + field + " " + what);
}

signal::PeakFinderConfig finder_config(const PeakStepConfig& c) {
    return {c.min_step_s, c.min_peak_mps2, c.min_drop_mps2, c.confirm_s};
}

double seconds(int64_t ns) { return static_cast<double>(ns) * 1e-9; }

}  // namespace

PeakStepDetector::PeakStepDetector(const PeakStepConfig& c)
    : c_(c), norm_lp_(c.lowpass_hz), gravity_lp_(c.gravity_window_s), peaks_(finder_config(c)) {
    require(c.lowpass_hz > 0, "lowpass_hz", "must be positive");
    require(c.gravity_window_s > 0, "gravity_window_s", "must be positive");
    require(c.min_drop_mps2 > 0, "min_drop_mps2", "must be positive");
    require(c.confirm_s > 0, "confirm_s", "must be positive");
    require(c.min_step_s >= 0, "min_step_s", "must not be negative");
    require(c.max_step_s > c.min_step_s, "max_step_s", "must be longer than min_step_s");
    require(c.stairs_rate_mps > 0, "stairs_rate_mps", "must be positive");
    for (auto& f : up_lp_) f = signal::FirstOrderLowPass(c.gravity_window_s);
}

int64_t PeakStepDetector::latency_ns() const { return static_cast<int64_t>(std::ceil(c_.confirm_s * 1e9)); }

void PeakStepDetector::reset() {
    norm_lp_.reset();
    gravity_lp_.reset();
    for (auto& f : up_lp_) f.reset();
    peaks_.reset();
    started_ = walking_ = false;
    t_last_ns_ = last_event_ns_ = last_peak_ns_ = 0;
    period_s_ = yaw_rad_ = yaw_at_event_rad_ = signal_ = vertical_rate_mps_ = 0.0;
    pending_count_ = pending_next_ = 0;
}

void PeakStepDetector::sample(int64_t t_ns, const double a[3], const double w[3]) {
    const double norm = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    double up[3];
    for (int i = 0; i < 3; ++i) up[i] = up_lp_[i].push(t_ns, a[i]);
    const double up_norm = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (started_ && up_norm > 0) {
        // Rotation about up is counter-clockwise seen from above; heading is clockwise.
        const double rate_up = (w[0] * up[0] + w[1] * up[1] + w[2] * up[2]) / up_norm;
        yaw_rad_ -= rate_up * seconds(t_ns - t_last_ns_);
    }
    if (!started_) {
        started_ = true;
        last_event_ns_ = t_ns;
    }
    t_last_ns_ = t_ns;
    signal_ = norm_lp_.push(t_ns, norm) - gravity_lp_.push(t_ns, norm);
    signal::Peak p;
    if (peaks_.push(t_ns, signal_, p)) on_peak(p);
    signal::Peak candidate;
    if (!peaks_.pending(candidate) && seconds(t_ns - last_event_ns_) >= c_.max_step_s) pause_until(t_ns);
}

int PeakStepDetector::mode_of(double heading_change_rad) const {
    if (vertical_rate_mps_ >= c_.stairs_rate_mps) return PN_STEP_MODE_UPSTAIRS;
    if (vertical_rate_mps_ <= -c_.stairs_rate_mps) return PN_STEP_MODE_DOWNSTAIRS;
    if (std::fabs(heading_change_rad) * 180.0 / M_PI > c_.turn_deg) return PN_STEP_MODE_TURNING;
    return PN_STEP_MODE_STRAIGHT;
}

// A pause from the last event to t_ns: one STATIC step; the valley restarts.
void PeakStepDetector::pause_until(int64_t t_ns) {
    if (t_ns <= last_event_ns_) return;
    StepEvent e;
    e.t_start_ns = last_event_ns_;
    e.t_ns = t_ns;
    e.accel_max_mps2 = e.accel_min_mps2 = signal_;
    e.heading_change_rad = yaw_rad_ - yaw_at_event_rad_;
    e.motion_mode = PN_STEP_MODE_STATIC;
    queue(e);
    walking_ = false;
    last_event_ns_ = t_ns;
    yaw_at_event_rad_ = yaw_rad_;
    peaks_.restart_valley(signal_);
}

void PeakStepDetector::on_peak(const signal::Peak& p) {
    const double since_peak_s = seconds(p.t_ns - last_peak_ns_);
    StepEvent e;
    e.t_ns = p.t_ns;
    e.accel_max_mps2 = p.value;
    e.accel_min_mps2 = p.valley;
    if (walking_ && since_peak_s <= c_.max_step_s) {
        e.t_start_ns = last_peak_ns_;
        period_s_ = since_peak_s;
    } else {
        // The first step of a bout ends at its first peak and began about a
        // step period before it (the last one walked, else the middle of the
        // accepted range); a gap before that not yet reported is a pause.
        const double period_s = period_s_ > 0 ? period_s_ : 0.5 * (c_.min_step_s + c_.max_step_s);
        const int64_t start = std::max(last_event_ns_, p.t_ns - static_cast<int64_t>(period_s * 1e9));
        if (start > last_event_ns_) pause_until(start);
        e.t_start_ns = std::max(last_event_ns_, start);
    }
    const double span_s = seconds(e.t_ns - e.t_start_ns);
    e.frequency_hz = span_s > 0 ? 1.0 / span_s : 0.0;
    e.heading_change_rad = yaw_rad_ - yaw_at_event_rad_;
    e.motion_mode = mode_of(e.heading_change_rad);
    if (!std::isfinite(e.accel_min_mps2)) e.accel_min_mps2 = e.accel_max_mps2;
    queue(e);
    walking_ = true;
    last_peak_ns_ = last_event_ns_ = p.t_ns;
    yaw_at_event_rad_ = yaw_rad_;
}

void PeakStepDetector::finish() {
    signal::Peak p;
    if (peaks_.pending(p)) on_peak(p);
    peaks_.reset();
    if (started_ && seconds(t_last_ns_ - last_event_ns_) >= c_.max_step_s) pause_until(t_last_ns_);
}

void PeakStepDetector::queue(const StepEvent& e) {
    if (pending_next_ == pending_count_) pending_next_ = pending_count_ = 0;
    if (pending_count_ < 3) pending_[pending_count_++] = e;
}

bool PeakStepDetector::next_pending(StepEvent& out) {
    if (pending_next_ >= pending_count_) return false;
    out = pending_[pending_next_++];
    return true;
}

}  // namespace pednav::pdr
