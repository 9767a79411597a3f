// SPDX-License-Identifier: Apache-2.0
// A centred moving average over a time window, streamed: each sample's mean
// over the samples within half a window of it, handed out once the window
// is complete (half a window after the sample), so with a look-ahead of
// half_window_ns() and no phase lag. The rings are allocated at
// construction; push() allocates nothing.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "centred_window.hpp"

namespace pednav::signal {

class CentredMovingAverage {
public:
    // window_s >= 0 (0: every sample is its own mean); max_rate_hz: the
    // highest sample rate the rings must hold the window at.
    CentredMovingAverage(double window_s, double max_rate_hz)
        : h_ns_(signal::half_window_ns(window_s)), size_(ring_size_for_window(window_s, max_rate_hz)), mask_(size_ - 1),
          t_(size_), v_(size_) {
        if (!(window_s >= 0) || !(max_rate_hz > 0))
            throw std::invalid_argument("moving average: window must be >= 0 s and rate > 0 Hz");
    }

    int64_t half_window_ns() const { return h_ns_; }

    // One sample (t_ns increasing). out(t_ns, mean) for every sample whose
    // window is now complete, oldest first.
    template <class Out>
    void push(int64_t t_ns, double value, Out&& out) {
        if (n_ - lo_ >= size_) throw std::length_error("moving average: ring full (rate above the capacity)");
        t_[n_ & mask_] = t_ns;
        v_[n_ & mask_] = value;
        ++n_;
        while (c_ < n_ && t_[c_ & mask_] + h_ns_ < t_ns) emit_centre(out);
    }

    // End of stream: the remaining samples with the part of their window there is.
    template <class Out>
    void flush(Out&& out) {
        while (c_ < n_) emit_centre(out);
    }

    void reset() { n_ = c_ = lo_ = hi_ = 0, sum_ = 0; }

private:
    template <class Out>
    void emit_centre(Out&& out) {
        const int64_t t = t_[c_ & mask_];
        slide_centred_window(t_.data(), mask_, n_, c_, t, h_ns_, hi_, lo_,
                             [this](uint64_t i) { sum_ += v_[i & mask_]; },
                             [this](uint64_t i) { sum_ -= v_[i & mask_]; });
        out(t, sum_ / static_cast<double>(hi_ - lo_));
        ++c_;
    }

    int64_t h_ns_;
    uint64_t size_, mask_;
    std::vector<int64_t> t_;
    std::vector<double> v_;
    uint64_t n_ = 0, c_ = 0, lo_ = 0, hi_ = 0;
    double sum_ = 0;
};

}  // namespace pednav::signal
