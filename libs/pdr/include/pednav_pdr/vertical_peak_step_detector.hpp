// SPDX-License-Identifier: Apache-2.0
// Steps of a body-worn sensor (waist, belt) from the peaks of its vertical
// acceleration, and the motion mode of each step (waist paper, sec. 3.1 and
// 3.3, Table 1).
//
// Vertical acceleration after gravity compensation, whatever the sensor's
// tilt (vertical_acceleration.hpp): the gravity direction u is the
// low-passed specific force (time constant gravity_time_constant_s; its mean
// over a few steps is gravity), and a_v = f . u - |g_lp| (|g_lp| also
// absorbs the accelerometer's scale error). a_v is smoothed by a centred moving average (smoothing_window_s,
// no phase lag) and its local maxima over +-min_step_interval_s are the
// candidate peaks. A candidate is a step when
//   C1 (eq. 3.2): its maximum is above accel_max_threshold_mps2 and the
//       minimum since the previous candidate below accel_min_threshold_mps2;
//   C2 (eq. 3.3): the interval to the neighbouring step is within
//       (min_step_interval_s, max_step_interval_s) (walking cadence: 1-4 Hz).
// C1's thresholds are a hysteresis: a step that continues a walking bout
// (within max_step_interval_s of its last step) needs only its peak above
// bout_accel_max_threshold_mps2 and its minimum below
// bout_accel_min_threshold_mps2, weaker than the thresholds that start a
// bout (the decelerating steps before a stop and a turn's pivot steps
// bounce the pelvis less than walking does; an isolated weak peak in a
// stop is still no step).
// The first step of a walking bout has no step before it: it is held until
// the next candidate confirms the cadence (an isolated peak is no step), so
// the detector's look-ahead is max_step_interval_s plus the two half windows.
//
// Motion mode (Table 1), per step:
//   C3 (eq. 3.4): the barometric altitude change over the step (the
//       altimeter's slope over baro_window_s around the step, times the
//       step's duration) above +stairs_rise_min_m: upstairs, below it:
//       downstairs;
//   C4 (eq. 3.5): the rate of turn about the vertical (gyro . u) over the
//       step and the one before it (a stride, which cancels the pelvis' yaw
//       swing) above turn_rate_min_radps: turning; otherwise straight.
// C1 = C2 = 0, no step for max_step_interval_s after a bout's last step:
// one step record of mode static closes the bout.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_pdr/vertical_acceleration.hpp>
#include <pednav_signal/centred_moving_average.hpp>
#include <pednav_signal/centred_peak_finder.hpp>

namespace pednav::pdr {

// The values of PN_STEP_MODE_* (pn_types.h).
enum class MotionMode : int { unknown = 0, straight = 1, turning = 2, upstairs = 3, downstairs = 4, standing = 5 };

struct VerticalPeakStepConfig {
    double gravity_time_constant_s;   // low-pass of the specific force that gives the gravity direction, s (> 0)
    double smoothing_window_s;        // centred moving average of the vertical acceleration, s (>= 0)
    double accel_max_threshold_mps2;  // C1: the peak above this, m/s^2
    double accel_min_threshold_mps2;  // C1: the minimum within the step below this, m/s^2
    double bout_accel_max_threshold_mps2;  // C1 within a bout: the peak above this, m/s^2 (<= accel_max_threshold_mps2)
    double bout_accel_min_threshold_mps2;  // C1 within a bout: the minimum below this, m/s^2 (>= accel_min_threshold_mps2)
    double min_step_interval_s;       // C2: shortest step (also the peak window's half width), s (> 0)
    double max_step_interval_s;       // C2: longest step, s (> min_step_interval_s)
    double stairs_rise_min_m;         // C3: altitude change over one step that makes it stairs, m (> 0)
    double baro_window_s;             // C3: span of the altimeter slope around the step, s (> 0)
    double turn_rate_min_radps;       // C4: rate of turn that makes a step turning, rad/s (> 0)
    barometry::BarometricAltimeterConfig baro;
};

// Fills a config from a params view (number(key)) under the field names;
// the altimeter's under "baro_" (barometric_altimeter_config).
template <class Params>
VerticalPeakStepConfig vertical_peak_step_config(Params& p) {
    VerticalPeakStepConfig c;
    c.gravity_time_constant_s = p.number("gravity_time_constant_s");
    c.smoothing_window_s = p.number("smoothing_window_s");
    c.accel_max_threshold_mps2 = p.number("accel_max_threshold_mps2");
    c.accel_min_threshold_mps2 = p.number("accel_min_threshold_mps2");
    c.bout_accel_max_threshold_mps2 = p.number("bout_accel_max_threshold_mps2");
    c.bout_accel_min_threshold_mps2 = p.number("bout_accel_min_threshold_mps2");
    c.min_step_interval_s = p.number("min_step_interval_s");
    c.max_step_interval_s = p.number("max_step_interval_s");
    c.stairs_rise_min_m = p.number("stairs_rise_min_m");
    c.baro_window_s = p.number("baro_window_s");
    c.turn_rate_min_radps = p.number("turn_rate_min_radps");
    c.baro = barometry::barometric_altimeter_config(p, "baro_");
    return c;
}

struct VerticalStepEvent {
    int64_t t_start_ns = 0, t_ns = 0;  // [previous step, this peak]
    double accel_max_mps2 = 0, accel_min_mps2 = 0;  // filtered vertical acceleration within the step
    double frequency_hz = 0;           // 1 / step duration; 0 for a static record
    double heading_change_rad = 0;     // about the vertical over the step, clockwise positive
    double altitude_change_m = 0;      // barometric, over the step; 0 without a barometer
    MotionMode mode = MotionMode::unknown;
};

class VerticalPeakStepDetector {
public:
    // Throws std::invalid_argument for a config out of range. max_rate_hz:
    // the highest IMU rate the rings must hold.
    VerticalPeakStepDetector(const VerticalPeakStepConfig& config, double max_rate_hz);

    // Fixed look-ahead: a step at t is reported once an IMU sample after
    // t + latency_ns() has been pushed.
    int64_t latency_ns() const { return latency_ns_; }

    // Steps and static records reach `out` (a std::function-free callback is
    // stored per call: the lambda must outlive the call only).
    template <class Out>
    void push_imu(int64_t t_ns, const double accel_mps2[3], const double gyro_radps[3], Out&& out) {
        using O = std::remove_reference_t<Out>;
        sink_ = [](void* o, const VerticalStepEvent& e) { (*static_cast<O*>(o))(e); };
        sink_user_ = const_cast<void*>(static_cast<const void*>(&out));
        on_imu(t_ns, accel_mps2, gyro_radps);
    }
    template <class Out>
    void flush(Out&& out) {
        using O = std::remove_reference_t<Out>;
        sink_ = [](void* o, const VerticalStepEvent& e) { (*static_cast<O*>(o))(e); };
        sink_user_ = const_cast<void*>(static_cast<const void*>(&out));
        on_flush();
    }
    void push_baro(int64_t t_ns, double pressure_pa);

    // Counted over the stream: steps emitted (static records not counted).
    int64_t steps() const { return steps_; }
    const barometry::BarometricAltimeter& altimeter() const { return altimeter_; }

    void reset();

private:
    struct Candidate {
        int64_t t_ns;
        double max_mps2, min_mps2;
        double yaw_rad;  // cumulative rate of turn about the vertical, clockwise
    };
    void on_imu(int64_t t_ns, const double a[3], const double w[3]);
    void on_flush();
    void on_filtered(int64_t t_ns, double a_v);
    void on_judged(int64_t t_ns, double a_v, bool peak);
    void on_candidate(const Candidate& c);
    void emit_step(const Candidate& c, int64_t t_start_ns, double yaw_start_rad);
    void emit(const VerticalStepEvent& e);
    double altitude_at(int64_t t_ns) const;
    double altitude_change_m(int64_t t_ns, double duration_s) const;

    VerticalPeakStepConfig c_;
    int64_t latency_ns_;
    VerticalAcceleration vertical_;
    signal::CentredMovingAverage smoother_;
    signal::CentredPeakFinder peaks_;
    barometry::BarometricAltimeter altimeter_;

    // Per-sample ring of the cumulative yaw, by sample number (the smoother
    // and the peak finder hand samples out in order).
    std::vector<double> yaw_ring_;
    uint64_t yaw_mask_;
    uint64_t pushed_ = 0, judged_ = 0;

    int64_t t_last_ns_ = 0;
    double yaw_rad_ = 0;

    double min_since_candidate_;
    bool bout_open_ = false, has_pending_ = false;
    Candidate last_{}, pending_{};
    int64_t last_start_ns_ = 0;  // the last step's start and the yaw there
    double last_start_yaw_ = 0;
    int64_t steps_ = 0;

    // Altitude readings for C3, a ring of (t, altitude).
    std::vector<int64_t> alt_t_;
    std::vector<double> alt_m_;
    uint64_t alt_n_ = 0;

    void (*sink_)(void*, const VerticalStepEvent&) = nullptr;
    void* sink_user_ = nullptr;
};

}  // namespace pednav::pdr
