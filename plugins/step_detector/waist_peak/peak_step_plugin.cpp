// SPDX-License-Identifier: Apache-2.0
// Waist (belt) step detector: peaks of the vertical acceleration after
// gravity compensation, the paper's step conditions and its motion modes
// (pednav_pdr/vertical_peak_step_detector.hpp). One PN_REC_STEP per step, stamped at
// its peak, and one of mode static when a walking bout ends.
#include <algorithm>
#include <cmath>
#include <memory>

#include <pednav_barometry/params_schema.hpp>
#include <pednav_pdr/vertical_peak_step_detector.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
using pednav::pdr::VerticalPeakStepDetector;
using pednav::pdr::VerticalStepEvent;

class WaistPeakSteps : public StepDetector {
public:
    static constexpr const char* kId = "org.pednav.waist.steps.peak";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:waist", "uses:baro", nullptr};
    static constexpr const char* kName = "waist steps, vertical acceleration peaks";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "peaks of the smoothed vertical acceleration (gravity direction from the low-passed specific force, any "
        "tilt) with the waist paper's conditions C1-C4 (eq. 3.2-3.5) and motion modes (Table 1)";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "gravity_time_constant_s": {"type": "number", "x-unit": "s", "minimum": 0.05, "maximum": 60, "default": 1.0,
      "description": "low-pass of the specific force whose direction is the vertical"},
    "smoothing_window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 1, "default": 0.2,
      "description": "centred moving average of the vertical acceleration (sec. 3.1's smooth filtering)"},
    "accel_max_threshold_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": -10, "maximum": 50, "default": 0.15,
      "description": "C1 (eq. 3.2): a step's peak is above this; above accel_min_threshold_mps2"},
    "accel_min_threshold_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": -50, "maximum": 10, "default": -0.2,
      "description": "C1 (eq. 3.2): the minimum within the step is below this"},
    "bout_accel_max_threshold_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": -10, "maximum": 50, "default": 0.1,
      "description": "C1 for a step that continues a bout (within max_step_interval_s of its last step): its peak is above this (at most accel_max_threshold_mps2; the steps before a stop and a turn's pivot steps bounce the pelvis less)"},
    "bout_accel_min_threshold_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": -50, "maximum": 10, "default": -0.1,
      "description": "C1 for a step that continues a bout: its minimum is below this (at least accel_min_threshold_mps2, below bout_accel_max_threshold_mps2)"},
    "min_step_interval_s": {"type": "number", "x-unit": "s", "minimum": 0.05, "maximum": 2, "default": 0.25,
      "description": "C2 (eq. 3.3): shortest step (4 Hz), also half the peak window"},
    "max_step_interval_s": {"type": "number", "x-unit": "s", "minimum": 0.1, "maximum": 5, "default": 1.5,
      "description": "C2 (eq. 3.3): longest step (0.67 Hz: the pivot steps of a U-turn are slower than walking); above min_step_interval_s; sets the look-ahead"},
    "stairs_rise_min_m": {"type": "number", "x-unit": "m", "minimum": 0.001, "maximum": 1, "default": 0.07,
      "description": "C3 (eq. 3.4): barometric altitude change over one step that makes it upstairs (or, negative, downstairs)"},
    "baro_window_s": {"type": "number", "x-unit": "s", "minimum": 0.1, "maximum": 20, "default": 2.0,
      "description": "C3: the altitude change is the altimeter's slope over this span around the step"},
    "turn_rate_min_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0.001, "maximum": 10, "default": 0.3,
      "description": "C4 (eq. 3.5): rate of turn about the vertical over the step and the one before it that makes it turning"},
    )json" PEDNAV_BAROMETER_PARAMS_SCHEMA(2.0, 0.5, 1.0, 3.4, 0.5, 2.0) R"json(
  }
})json";
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_BARO);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_STEP);

    WaistPeakSteps(Params& p, const CreateContext& ctx) {
        const pednav::pdr::VerticalPeakStepConfig c = pednav::pdr::vertical_peak_step_config(p);
        if (c.accel_max_threshold_mps2 <= c.accel_min_threshold_mps2)
            Params::fail("accel_max_threshold_mps2", "must be above accel_min_threshold_mps2");
        if (c.bout_accel_max_threshold_mps2 > c.accel_max_threshold_mps2)
            Params::fail("bout_accel_max_threshold_mps2", "must be at most accel_max_threshold_mps2");
        if (c.bout_accel_min_threshold_mps2 < c.accel_min_threshold_mps2)
            Params::fail("bout_accel_min_threshold_mps2", "must be at least accel_min_threshold_mps2");
        if (c.bout_accel_max_threshold_mps2 <= c.bout_accel_min_threshold_mps2)
            Params::fail("bout_accel_max_threshold_mps2", "must be above bout_accel_min_threshold_mps2");
        if (c.max_step_interval_s <= c.min_step_interval_s)
            Params::fail("max_step_interval_s", "must be above min_step_interval_s");
        detector_ = std::make_unique<VerticalPeakStepDetector>(c, std::max(2.0 * ctx.imu_rate_hz, 1000.0));
    }

    void on_imu(const pn_imu_t& imu) override {
        detector_->push_imu(imu.header.t_ns, imu.accel_mps2, imu.gyro_radps, out_);
    }
    void on_baro(const pn_baro_t& b) override { detector_->push_baro(b.header.t_ns, b.pressure_pa); }
    void on_flush() override { detector_->flush(out_); }
    int64_t latency_ns() const override { return detector_->latency_ns(); }

private:
    struct Out {
        WaistPeakSteps* self;
        void operator()(const VerticalStepEvent& e) const { self->out(e); }
    };
    void out(const VerticalStepEvent& e) {
        auto s = make_record<pn_step_t>(e.t_ns);
        s.t_start_ns = e.t_start_ns;
        s.accel_max_mps2 = e.accel_max_mps2;
        s.accel_min_mps2 = e.accel_min_mps2;
        s.accel_peak_to_peak_mps2 = e.accel_max_mps2 - e.accel_min_mps2;
        s.frequency_hz = e.frequency_hz;
        s.motion_mode = static_cast<int32_t>(e.mode);
        emit(s);
    }

    std::unique_ptr<VerticalPeakStepDetector> detector_;
    Out out_{this};
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.waist.steps", "1.0.0", WaistPeakSteps)
