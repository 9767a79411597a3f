// SPDX-License-Identifier: Apache-2.0
#include "pednav_zupt_ins/stance_detector.hpp"

namespace pednav::zupt_ins {

using signal::half_window_ns;
using signal::ring_size_for;
using signal::ring_size_for_window;

StanceDetector::StanceDetector(Kind kind, const StanceWindows& w, double max_rate_hz)
    : kind_(kind),
      adaptive_(w.adaptive_window_s > 0),
      adaptive_ratio_(w.adaptive_ratio),
      adaptive_max_(w.adaptive_max),
      h1_(half_window_ns(w.window_s)),
      h2_(half_window_ns(w.adaptive_window_s)),
      h3_(half_window_ns(w.median_window_s)) {
    cap1_ = ring_size_for_window(w.window_s, max_rate_hz);
    mask1_ = cap1_ - 1;
    t1_.reset(new int64_t[cap1_]());
    in_.reset(new In[cap1_]());
    cap2_ = adaptive_ ? ring_size_for_window(w.adaptive_window_s, max_rate_hz) : 0;
    cap3_ = ring_size_for_window(w.median_window_s, max_rate_hz);
    // A sample is needed by stage 2 or 3 for at most cap2_ + cap3_ samples
    // after it entered stage 2 (each stage holds at most its capacity).
    const uint64_t cap_d = ring_size_for(cap2_ + cap3_ + 1);
    maskd_ = cap_d - 1;
    td_.reset(new int64_t[cap_d]());
    st_.reset(new double[cap_d]());
    fx_.reset(new bool[cap_d]());
    sn_.reset(new bool[cap_d]());
    // The deque holds at most the stage-2 window.
    const uint64_t cap_dq = ring_size_for(cap2_);
    dq_.reset(new uint64_t[cap_dq]());
    minimum_.ring = dq_.get();
    minimum_.mask = cap_dq - 1;
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
