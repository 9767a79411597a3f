#include "pednav_foot/stance_detector.hpp"

#include <algorithm>

namespace pednav::foot {

namespace {
int64_t half_ns(double window_s) { return static_cast<int64_t>(std::llround(window_s * 0.5e9)); }
}  // namespace

StanceDetector::StanceDetector(Kind kind, const StanceWindows& w, double max_rate_hz)
    : kind_(kind),
      stat_(half_ns(w.window_s), detail::capacity_for(w.window_s, max_rate_hz)),
      adapt_(half_ns(w.adaptive_window_s), detail::capacity_for(w.adaptive_window_s, max_rate_hz)),
      vote_(half_ns(w.median_window_s), detail::capacity_for(w.median_window_s, max_rate_hz)),
      adaptive_(w.adaptive_window_s > 0),
      adaptive_ratio_(w.adaptive_ratio),
      adaptive_max_(w.adaptive_max) {
    stat_.acc().is_shoe = kind == Kind::Shoe;
    adapt_.acc().init(detail::capacity_for(w.adaptive_window_s, max_rate_hz));
}

StanceDetector::StanceDetector(const MultiConditionConfig& c, double max_rate_hz)
    : StanceDetector(Kind::MultiCondition, c, max_rate_hz) {
    multi_ = c;
}

StanceDetector::StanceDetector(const ShoeConfig& c, double max_rate_hz) : StanceDetector(Kind::Shoe, c, max_rate_hz) {
    shoe_ = c;
    shoe_ia_ = 1.0 / (c.accel_sd_mps2 * c.accel_sd_mps2);
    shoe_iw_ = 1.0 / (c.gyro_sd_radps * c.gyro_sd_radps);
}

}  // namespace pednav::foot
