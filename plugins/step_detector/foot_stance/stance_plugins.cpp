// SPDX-License-Identifier: Apache-2.0
// Foot stance detectors as step_detector plugins: one PN_REC_GAIT_PHASE per
// IMU sample, stamped with the time of the sample it classifies, emitted
// latency_ns() after it (centred windows).
#include <memory>

#include <pednav_zupt_ins/stance_detector.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
using pednav::zupt_ins::StanceDecision;
using pednav::zupt_ins::StanceDetector;

// Ring buffers are sized for this rate or twice the nominal rate, whichever
// is larger, so the windows hold at any rate up to it.
double capacity_rate(const CreateContext& ctx) { return std::max(2.0 * ctx.imu_rate_hz, 1000.0); }

class StanceBase : public StepDetector {
public:
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_IMU);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_GAIT_PHASE);

    void on_imu(const pn_imu_t& imu) override {
        detector_->push(imu.header.t_ns, imu.accel_mps2, imu.gyro_radps, [this](const StanceDecision& d) { out(d); });
    }
    void on_flush() override {
        detector_->flush([this](const StanceDecision& d) { out(d); });
    }
    int64_t latency_ns() const override { return detector_->latency_ns(); }

protected:
    std::unique_ptr<StanceDetector> detector_;

private:
    void out(const StanceDecision& d) {
        auto g = make_record<pn_gait_phase_t>(d.t_ns);
        g.stance = d.stance ? 1 : 0;
        g.statistic = d.statistic;
        emit(g);
    }
};

class MultiConditionStance : public StanceBase {
public:
    static constexpr const char* kId = "org.pednav.foot.stance.multicondition";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:foot", nullptr};
    static constexpr const char* kName = "foot stance, multi-condition";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "acceleration magnitude band, std of |a| over a centred window, gyro norm, majority filter "
        "(foot-imu-zupt-zaru-ekf sec. 2.3), windows in seconds";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "accel_min_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 100, "default": 9,
      "description": "C1: lower bound of the band on |a| (eq. 17); below accel_max_mps2"},
    "accel_max_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 100, "default": 11,
      "description": "C1: upper bound of the band on |a| (eq. 17); above accel_min_mps2"},
    "accel_std_max_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 100, "default": 0.5,
      "description": "C2: stance needs the std of |a| over the window below this (eq. 20)"},
    "gyro_max_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 100, "default": 1.0,
      "description": "C3: stance needs |w| below this (eq. 22)"},
    "window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 2, "default": 0.15,
      "description": "centred window of eq. (18)-(19)"},
    "median_window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 2, "default": 0.11,
      "description": "majority filter over the stance decisions, a centred window"},
    "adaptive_window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 10, "default": 0,
      "description": "adaptive threshold: centred window of the running minimum of the statistic max(std|a| / accel_std_max_mps2, |w| / gyro_max_radps); 0 = the paper's fixed conditions only"},
    "adaptive_ratio": {"type": "number", "minimum": 1, "maximum": 1e6, "default": 2.0,
      "description": "adaptive threshold: a sample is also stance when the statistic is at most this times its running minimum (and below adaptive_max)"},
    "adaptive_max": {"type": "number", "minimum": 0, "maximum": 1e12, "default": 4.0,
      "description": "adaptive threshold: the statistic must also be below this"}
  }
})json";

    MultiConditionStance(Params& p, const CreateContext& ctx) {
        const pednav::zupt_ins::MultiConditionConfig c = pednav::zupt_ins::multicondition_config(p);
        if (c.accel_min_mps2 >= c.accel_max_mps2)
            Params::fail("accel_max_mps2", "must be greater than accel_min_mps2");
        detector_ = std::make_unique<StanceDetector>(c, capacity_rate(ctx));
    }
};

class ShoeStance : public StanceBase {
public:
    static constexpr const char* kId = "org.pednav.foot.stance.shoe";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:foot", nullptr};
    static constexpr const char* kName = "foot stance, SHOE/GLRT";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "stance hypothesis optimal detector (Skog et al. 2010) over a centred window in seconds, "
        "adaptive threshold relative to the minimum over a gait cycle, majority filter";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "accel_sd_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 1e-6, "maximum": 100, "default": 1.0,
      "description": "sigma_a of the GLRT"},
    "gyro_sd_radps": {"type": "number", "x-unit": "rad/s", "minimum": 1e-6, "maximum": 100, "default": 0.5,
      "description": "sigma_w of the GLRT"},
    "threshold": {"type": "number", "minimum": 0, "maximum": 1e12, "default": 0.5,
      "description": "gamma: stance when the test statistic T < gamma (T is normalised by the window length)"},
    "gravity_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 20, "default": 0,
      "description": "g in the test; 0 = the window's |mean a|, which makes the test blind to accelerometer scale errors"},
    "window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 2, "default": 0.06,
      "description": "centred GLRT window"},
    "median_window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 2, "default": 0.05,
      "description": "majority filter over the stance decisions, a centred window"},
    "adaptive_window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 10, "default": 1.0,
      "description": "adaptive threshold: centred window of the running minimum of T (longer than one gait cycle); 0 = fixed threshold only"},
    "adaptive_ratio": {"type": "number", "minimum": 1, "maximum": 1e6, "default": 3.0,
      "description": "adaptive threshold: a sample is also stance when T is at most this times its running minimum (and below adaptive_max)"},
    "adaptive_max": {"type": "number", "minimum": 0, "maximum": 1e12, "default": 60,
      "description": "adaptive threshold: T must also be below this"}
  }
})json";

    ShoeStance(Params& p, const CreateContext& ctx) {
        const pednav::zupt_ins::ShoeConfig c = pednav::zupt_ins::shoe_config(p);
        detector_ = std::make_unique<StanceDetector>(c, capacity_rate(ctx));
    }
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.foot.stance", "1.0.0", MultiConditionStance, ShoeStance)
