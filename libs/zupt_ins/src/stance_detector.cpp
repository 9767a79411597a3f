#include "pednav_zupt_ins/stance_detector.hpp"

#include <algorithm>

namespace pednav::zupt_ins {

namespace {
int64_t half_ns(double window_s) { return static_cast<int64_t>(std::llround(window_s * 0.5e9)); }

// A window of window_s at up to rate_hz, plus margin, as a power of two.
uint64_t capacity_for(double window_s, double rate_hz) {
    const uint64_t want = static_cast<uint64_t>(std::ceil(window_s * rate_hz)) + 64;
    uint64_t cap = 16;
    while (cap < want) cap <<= 1;
    return cap;
}
}  // namespace

StanceDetector::StanceDetector(Kind kind, const StanceWindows& w, double max_rate_hz)
    : kind_(kind),
      adaptive_(w.adaptive_window_s > 0),
      adaptive_ratio_(w.adaptive_ratio),
      adaptive_max_(w.adaptive_max),
      h1_(half_ns(w.window_s)),
      h2_(half_ns(w.adaptive_window_s)),
      h3_(half_ns(w.median_window_s)) {
    cap1_ = capacity_for(w.window_s, max_rate_hz);
    mask1_ = cap1_ - 1;
    t1_.reset(new int64_t[cap1_]());
    in_.reset(new In[cap1_]());
    cap2_ = adaptive_ ? capacity_for(w.adaptive_window_s, max_rate_hz) : 0;
    cap3_ = capacity_for(w.median_window_s, max_rate_hz);
    // A sample is needed by stage 2 or 3 for at most cap2_ + cap3_ samples
    // after it entered stage 2 (each stage holds at most its capacity).
    uint64_t cap_d = 16;
    while (cap_d < cap2_ + cap3_ + 1) cap_d <<= 1;
    maskd_ = cap_d - 1;
    td_.reset(new int64_t[cap_d]());
    st_.reset(new double[cap_d]());
    fx_.reset(new bool[cap_d]());
    sn_.reset(new bool[cap_d]());
    const uint64_t cap_dq = std::max<uint64_t>(cap2_, 16);
    dq_mask_ = cap_dq - 1;
    dq_.reset(new uint64_t[cap_dq]());
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

}  // namespace pednav::zupt_ins
