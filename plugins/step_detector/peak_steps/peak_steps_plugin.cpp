// SPDX-License-Identifier: Apache-2.0
// Steps of a chest-mounted or handheld sensor from the peaks of the low-pass
// filtered acceleration norm (pdr::PeakStepDetector): one PN_REC_STEP per
// step, from peak to peak, and one STATIC step per pause; up or down stairs
// while the barometer climbs or descends.
#include <pednav_barometry/params_schema.hpp>
#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_pdr/peak_step_detector.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;

class PeakSteps : public StepDetector {
public:
    static constexpr const char* kId = "org.pednav.pdr.steps.peak";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:chest", "mount:handheld", "uses:baro", nullptr};
    static constexpr const char* kName = "steps from acceleration-norm peaks";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "peaks of the low-pass filtered acceleration norm, one step from peak to peak (chest-imu-particle-filter-"
        "map-matching sec. 3.1), minimum interval and height, cadence check, filters in time for any rate and "
        "jittered samples; motion mode straight/turning/static, stairs from the barometer";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "lowpass_hz": {"type": "number", "x-unit": "Hz", "minimum": 0.2, "maximum": 20, "default": 3.0,
      "description": "-3 dB frequency of the second-order low-pass on |a| (two first-order stages in time)"},
    "gravity_window_s": {"type": "number", "x-unit": "s", "minimum": 0.1, "maximum": 60, "default": 2.0,
      "description": "time constant of the gravity estimate (slow low-pass of |a|), subtracted from the signal, and of the up direction for the turn rate"},
    "min_peak_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 50, "default": 0.4,
      "description": "a step's peak is at least this above gravity"},
    "min_drop_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0.01, "maximum": 50, "default": 0.4,
      "description": "a peak is confirmed once the signal has fallen this far below it"},
    "confirm_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 2, "default": 0.3,
      "description": "or this long after it without a higher value: the detector's look-ahead"},
    "min_step_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 2, "default": 0.3,
      "description": "minimum interval between two peaks (refractory time after a peak)"},
    "max_step_s": {"type": "number", "x-unit": "s", "minimum": 0.1, "maximum": 5, "default": 1.2,
      "description": "cadence check: peaks further apart do not make a step; a gap this long is a pause (a STATIC step); above min_step_s"},
    "turn_deg": {"type": "number", "x-unit": "deg", "minimum": 0, "maximum": 180, "default": 15,
      "description": "a step over which the heading (gyro about gravity) turned more than this is TURNING"},
    "stairs_rate_mps": {"type": "number", "x-unit": "m/s", "minimum": 0.01, "maximum": 10, "default": 0.15,
      "description": "a step while the barometric altitude climbs (descends) faster than this is UPSTAIRS (DOWNSTAIRS)"},
    )json" PEDNAV_BAROMETER_PARAMS_SCHEMA(5, 0.3, 1.0, 3.5, 0.1, 5) R"json(
  }
})json";
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_BARO);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_STEP);

    PeakSteps(Params& p, const CreateContext&)
        : detector_(config(p)), altimeter_(pednav::barometry::barometric_altimeter_config(p, "baro_")) {}

    void on_imu(const pn_imu_t& imu) override {
        detector_.push(imu.header.t_ns, imu.accel_mps2, imu.gyro_radps,
                       [this](const pednav::pdr::StepEvent& e) { out(e); });
    }
    void on_baro(const pn_baro_t& b) override {
        altimeter_.push(b.header.t_ns, b.pressure_pa);
        if (altimeter_.ready()) detector_.set_vertical_rate(altimeter_.vertical_rate_mps());
    }
    void on_flush() override {
        detector_.flush([this](const pednav::pdr::StepEvent& e) { out(e); });
    }
    int64_t latency_ns() const override { return detector_.latency_ns(); }

private:
    static pednav::pdr::PeakStepConfig config(Params& p) {
        const pednav::pdr::PeakStepConfig c = pednav::pdr::peak_step_config(p);
        if (c.max_step_s <= c.min_step_s)
            Params::fail("max_step_s", "is " + format_number(c.max_step_s) + " s, not above min_step_s (" +
                                           format_number(c.min_step_s) + " s)");
        return c;
    }
    void out(const pednav::pdr::StepEvent& e) {
        auto s = make_record<pn_step_t>(e.t_ns);
        s.t_start_ns = e.t_start_ns;
        s.accel_max_mps2 = e.accel_max_mps2;
        s.accel_min_mps2 = e.accel_min_mps2;
        s.accel_peak_to_peak_mps2 = e.accel_max_mps2 - e.accel_min_mps2;
        s.frequency_hz = e.frequency_hz;
        s.motion_mode = e.motion_mode;
        emit(s);
    }

    pednav::pdr::PeakStepDetector detector_;
    pednav::barometry::BarometricAltimeter altimeter_;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.pdr.steps.peak", "1.0.0", PeakSteps)
