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

// The window parameters both detectors share (defaults from the detector's config).
void read_windows(Params& p, pednav::zupt_ins::StanceWindows& w) {
    w.window_s = p.number("window_s", w.window_s, 0.0, 2.0);
    w.median_window_s = p.number("median_window_s", w.median_window_s, 0.0, 2.0);
    w.adaptive_window_s = p.number("adaptive_window_s", w.adaptive_window_s, 0.0, 10.0);
    w.adaptive_ratio = p.number("adaptive_ratio", w.adaptive_ratio, 1.0, 1e6);
    w.adaptive_max = p.number("adaptive_max", w.adaptive_max, 0.0, 1e12);
}

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

    MultiConditionStance(Params& p, const CreateContext& ctx) {
        pednav::zupt_ins::MultiConditionConfig c;
        c.accel_min_mps2 = p.number("accel_min_mps2", c.accel_min_mps2, 0.0, 100.0);
        c.accel_max_mps2 = p.number("accel_max_mps2", c.accel_max_mps2, 0.0, 100.0);
        c.accel_std_max_mps2 = p.number("accel_std_max_mps2", c.accel_std_max_mps2, 0.0, 100.0);
        c.gyro_max_radps = p.number("gyro_max_radps", c.gyro_max_radps, 0.0, 100.0);
        read_windows(p, c);
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

    ShoeStance(Params& p, const CreateContext& ctx) {
        pednav::zupt_ins::ShoeConfig c;
        c.accel_sd_mps2 = p.number("accel_sd_mps2", c.accel_sd_mps2, 1e-6, 100.0);
        c.gyro_sd_radps = p.number("gyro_sd_radps", c.gyro_sd_radps, 1e-6, 100.0);
        c.threshold = p.number("threshold", c.threshold, 0.0, 1e12);
        c.gravity_mps2 = p.number("gravity_mps2", c.gravity_mps2, 0.0, 20.0);
        read_windows(p, c);
        detector_ = std::make_unique<StanceDetector>(c, capacity_rate(ctx));
    }
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.foot.stance", "1.0.0", MultiConditionStance, ShoeStance)
