// SPDX-License-Identifier: Apache-2.0
// Steps of an upper-body sensor (chest, handheld phone) from the peaks of the
// low-pass filtered acceleration norm (chest-imu-particle-filter-map-matching
// sec. 3.1): one step from a peak to the next.
//
// The signal is |a| low-passed (a second-order filter in time, so any rate and
// jittered sample times give the same signal) minus gravity, itself a slow
// low-pass of |a| (it follows the sensor's own scale). Peaks come from
// signal::PeakFinder: at least min_peak_mps2 high, at least min_step_s apart,
// confirmed once the signal falls min_drop_mps2 below them or confirm_s after
// them. The cadence check: two peaks at most max_step_s apart make a step;
// a longer gap is a pause, reported as a STATIC step once it lasts max_step_s,
// and the next peak opens a walking bout (its step starts one step period
// before it). Each step carries the signal's maximum and minimum over it, its
// frequency, and a motion mode: up or down stairs while the barometer's
// vertical rate is beyond stairs_rate_mps, turning when the heading (the
// gyro about the gravity direction) turned more than turn_deg over the step,
// straight otherwise.
#pragma once

#include <cstdint>
#include <string>

#include <pednav/pn_types.h>
#include <pednav_signal/low_pass.hpp>
#include <pednav_signal/peak_finder.hpp>

namespace pednav::pdr {

struct PeakStepConfig {
    double lowpass_hz;        // -3 dB frequency of the low-pass on |a|, Hz (> 0)
    double gravity_window_s;  // time constant of the gravity estimate (slow low-pass of |a| and of a), s (> 0)
    double min_peak_mps2;     // a step's peak is at least this above gravity, m/s^2
    double min_drop_mps2;     // a peak is confirmed once the signal falls this far below it, m/s^2 (> 0)
    double confirm_s;         // or this long after it, s (> 0): the detector's look-ahead
    double min_step_s;        // shortest step (refractory time after a peak), s
    double max_step_s;        // longest step; a longer gap between peaks is a pause, s (> min_step_s)
    double turn_deg;          // heading change over a step that makes it TURNING, deg
    double stairs_rate_mps;   // barometric vertical rate that makes a step UPSTAIRS/DOWNSTAIRS, m/s (> 0)
};

// Fills a config from a params view (any type with number(key)) under the
// field names.
template <class Params>
PeakStepConfig peak_step_config(Params& p) {
    PeakStepConfig c;
    c.lowpass_hz = p.number("lowpass_hz");
    c.gravity_window_s = p.number("gravity_window_s");
    c.min_peak_mps2 = p.number("min_peak_mps2");
    c.min_drop_mps2 = p.number("min_drop_mps2");
    c.confirm_s = p.number("confirm_s");
    c.min_step_s = p.number("min_step_s");
    c.max_step_s = p.number("max_step_s");
    c.turn_deg = p.number("turn_deg");
    c.stairs_rate_mps = p.number("stairs_rate_mps");
    return c;
}

struct StepEvent {
    int64_t t_start_ns = 0, t_ns = 0;
    double accel_max_mps2 = 0.0, accel_min_mps2 = 0.0;  // of the signal (|a| low-passed minus gravity)
    double frequency_hz = 0.0;                          // 1 / step period; 0 for a pause
    double heading_change_rad = 0.0;                    // clockwise positive, gyro about gravity
    int motion_mode = PN_STEP_MODE_UNKNOWN;             // PN_STEP_MODE_*
};

class PeakStepDetector {
public:
    // Throws std::invalid_argument naming the field for a config out of range.
    explicit PeakStepDetector(const PeakStepConfig& config);

    // One IMU sample (t_ns increasing); calls on_step(const StepEvent&) for
    // each step or pause it completes.
    template <class OnStep>
    void push(int64_t t_ns, const double accel_mps2[3], const double gyro_radps[3], OnStep&& on_step) {
        sample(t_ns, accel_mps2, gyro_radps);
        StepEvent e;
        while (next_pending(e)) on_step(e);
    }
    // End of stream: the pending peak, and the pause after the last step.
    template <class OnStep>
    void flush(OnStep&& on_step) {
        StepEvent e;
        finish();
        while (next_pending(e)) on_step(e);
    }
    // The barometer's vertical rate now, m/s (from a barometric altimeter).
    void set_vertical_rate(double rate_mps) { vertical_rate_mps_ = rate_mps; }
    // Every step is reported at most this long after its time.
    int64_t latency_ns() const;
    // The last value of the signal (|a| low-passed minus gravity), m/s^2.
    double signal_mps2() const { return signal_; }
    void reset();

private:
    void sample(int64_t t_ns, const double a[3], const double w[3]);
    void on_peak(const signal::Peak& p);
    void pause_until(int64_t t_ns);
    void finish();
    bool next_pending(StepEvent& out);
    void queue(const StepEvent& e);
    int mode_of(double heading_change_rad) const;

    PeakStepConfig c_;
    signal::SecondOrderLowPass norm_lp_;
    signal::FirstOrderLowPass gravity_lp_, up_lp_[3];
    signal::PeakFinder peaks_;
    bool started_ = false, walking_ = false;
    int64_t t_last_ns_ = 0;
    int64_t last_event_ns_ = 0;  // end of the last step or pause reported
    int64_t last_peak_ns_ = 0;
    double period_s_ = 0.0;  // of the last walking step
    double yaw_rad_ = 0.0;   // heading turned since the start, clockwise positive
    double yaw_at_event_rad_ = 0.0;
    double signal_ = 0.0;
    double vertical_rate_mps_ = 0.0;
    StepEvent pending_[3];
    int pending_count_ = 0, pending_next_ = 0;
};

}  // namespace pednav::pdr
