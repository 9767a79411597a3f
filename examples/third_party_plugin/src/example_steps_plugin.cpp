// SPDX-License-Identifier: Apache-2.0
// com.example.steps.peak: a step detector for a chest-worn or handheld IMU,
// written as a third party writes one, with the installed pednav SDK.
//
// The signal is the specific force's norm minus gravity, low-passed by a
// first-order filter (a = a + alpha (x - a), alpha = 1 - exp(-2 pi f dt)).
// A step is a local maximum of it above `min_peak_mps2`, at least
// `min_step_s` after the previous step, that stays the largest value for
// `confirm_s` after it: the detector looks `confirm_s` ahead, which it
// declares through latency_ns() so the scheduler delays the other streams by
// as much. Each STEP carries the step's interval, its frequency and the
// signal's range within it (what step-length models such as Weinberg's read).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <pednav_sdk/library.hpp>

namespace {

using namespace pednav::sdk;

constexpr double kGravityMps2 = 9.80665;
constexpr double kPi = 3.14159265358979323846;

// The params: type, default, range, unit and meaning, in one place. The engine
// checks every config against it before create (an unknown key, a wrong type
// or a value out of range is refused naming the key), `pednav plugins --params`
// prints it, and Params (below) takes its defaults from it.
constexpr const char* kSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "lowpass_hz":    {"type": "number", "default": 3.0, "minimum": 0.5, "maximum": 20, "x-unit": "Hz",
                      "description": "corner frequency of the low-pass filter on the signal"},
    "min_peak_mps2": {"type": "number", "default": 0.6, "minimum": 0, "maximum": 20, "x-unit": "m/s^2",
                      "description": "smallest peak of the filtered signal that counts as a step"},
    "min_step_s":    {"type": "number", "default": 0.3, "minimum": 0.1, "maximum": 2, "x-unit": "s",
                      "description": "shortest time between two steps"},
    "confirm_s":     {"type": "number", "default": 0.2, "minimum": 0.02, "maximum": 1, "x-unit": "s",
                      "description": "how long a peak must stay the largest value (the look-ahead)"}
  }
})json";

constexpr const char* const kMounts[] = {"mount:chest", "mount:handheld", nullptr};

class ExamplePeakSteps : public StepDetector {
public:
    // The descriptor, read by PEDNAV_PLUGIN_LIBRARY.
    static constexpr const char* kId = "com.example.steps.peak";  // what configs name; never changes
    static constexpr const char* kName = "example peak step detector";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kVendor = "Example Labs";
    static constexpr const char* kDescription = "steps at confirmed peaks of the low-passed specific force norm";
    static constexpr const char* const* kFeatures = kMounts;  // "mount:<m>": the presets it suits
    static constexpr const char* kParamsSchema = ::kSchema;
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_IMU);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_STEP);

    // create: every param is read here (Params throws a ConfigError naming the
    // key for a bad value; the SDK turns it into PN_E_INVALID_CONFIG).
    ExamplePeakSteps(Params& p, const CreateContext&)
        : lowpass_hz_(p.number("lowpass_hz")),
          min_peak_mps2_(p.number("min_peak_mps2")),
          min_step_ns_(seconds_to_ns(p.number("min_step_s"))),
          confirm_ns_(seconds_to_ns(p.number("confirm_s"))) {}

    // The look-ahead: a step at t is emitted once input up to t + confirm_s is seen.
    int64_t latency_ns() const override { return confirm_ns_; }

    // process: one call per IMU sample, in time order.
    void on_imu(const pn_imu_t& imu) override {
        const double* f = imu.accel_mps2;
        const double x = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) - kGravityMps2;
        const int64_t t = imu.header.t_ns;
        if (last_t_ns_ == INT64_MIN) {
            signal_ = x;
            log(PNP_LOG_INFO, "first sample at t = " + std::to_string(t * 1e-9) + " s");
        } else {
            const double dt_s = static_cast<double>(t - last_t_ns_) * 1e-9;
            signal_ += (1 - std::exp(-2 * kPi * lowpass_hz_ * dt_s)) * (x - signal_);
        }
        last_t_ns_ = t;
        step_max_ = std::max(step_max_, signal_);
        step_min_ = std::min(step_min_, signal_);

        if (signal_ > min_peak_mps2_ && signal_ > peak_mps2_ &&
            (last_step_ns_ == INT64_MIN || t - last_step_ns_ >= min_step_ns_)) {
            peak_mps2_ = signal_;  // a new candidate (or a higher one)
            peak_t_ns_ = t;
        }
        if (peak_t_ns_ != INT64_MIN && t - peak_t_ns_ >= confirm_ns_) emit_step();
    }

    // flush: the end of the stream; a candidate not yet confirmed is dropped.
    void on_flush() override {
        log(PNP_LOG_INFO, std::to_string(steps_) + " steps");
    }

    // reset: the SDK builds a fresh object from the same params, so an
    // instance after reset is exactly one after create.

private:
    static int64_t seconds_to_ns(double s) { return static_cast<int64_t>(std::llround(s * 1e9)); }

    void emit_step() {
        auto step = make_record<pn_step_t>(peak_t_ns_);
        step.t_start_ns = last_step_ns_ == INT64_MIN ? peak_t_ns_ : last_step_ns_;
        const double period_s = static_cast<double>(peak_t_ns_ - step.t_start_ns) * 1e-9;
        step.frequency_hz = period_s > 0 ? 1 / period_s : 0;
        step.accel_max_mps2 = step_max_;
        step.accel_min_mps2 = step_min_;
        step.accel_peak_to_peak_mps2 = step_max_ - step_min_;
        step.motion_mode = PN_STEP_MODE_UNKNOWN;  // this detector does not classify the motion
        emit(step);
        ++steps_;
        last_step_ns_ = peak_t_ns_;
        peak_t_ns_ = INT64_MIN;
        peak_mps2_ = -HUGE_VAL;
        step_max_ = step_min_ = signal_;
    }

    const double lowpass_hz_;
    const double min_peak_mps2_;
    const int64_t min_step_ns_;
    const int64_t confirm_ns_;

    double signal_ = 0;
    int64_t last_t_ns_ = INT64_MIN;
    double peak_mps2_ = -HUGE_VAL;
    int64_t peak_t_ns_ = INT64_MIN;
    int64_t last_step_ns_ = INT64_MIN;
    double step_max_ = -HUGE_VAL, step_min_ = HUGE_VAL;
    long steps_ = 0;
};

}  // namespace

// The library: its id and version, and every plugin class it holds. This
// generates the descriptors, the noexcept trampolines (an exception becomes a
// status and a message) and the one exported symbol, pnp_entry_v1.
PEDNAV_PLUGIN_LIBRARY("com.example.steps", "1.0.0", ExamplePeakSteps)
