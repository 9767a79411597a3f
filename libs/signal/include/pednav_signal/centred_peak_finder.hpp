// SPDX-License-Identifier: Apache-2.0
// Local maxima of a stream over a centred time window: a sample is a peak
// when it is the largest within half a window on either side (on a tie, the
// earliest), so two peaks are always more than half a window apart. Each
// sample is judged once the half window after it has arrived, with the
// running maximum of a monotone deque (Lemire 2006) in O(1) amortised per
// sample. The rings are allocated at construction; push() allocates nothing.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "centred_window.hpp"

namespace pednav::signal {

class CentredPeakFinder {
public:
    CentredPeakFinder(double window_s, double max_rate_hz)
        : h_ns_(signal::half_window_ns(window_s)), size_(ring_size_for_window(window_s, max_rate_hz)), mask_(size_ - 1),
          t_(size_), v_(size_), dq_(size_) {
        if (!(window_s > 0) || !(max_rate_hz > 0))
            throw std::invalid_argument("peak finder: window must be > 0 s and rate > 0 Hz");
    }

    int64_t half_window_ns() const { return h_ns_; }

    // One sample (t_ns increasing). out(t_ns, value, is_peak) for every sample
    // now judged, oldest first.
    template <class Out>
    void push(int64_t t_ns, double value, Out&& out) {
        while (c_ < n_ && t_[c_ & mask_] + h_ns_ < t_ns) judge(out);
        const uint64_t oldest = tail_ > head_ ? dq_[head_ & mask_] : c_;
        if (n_ - (oldest < c_ ? oldest : c_) >= size_)
            throw std::length_error("peak finder: ring full (rate above the capacity)");
        t_[n_ & mask_] = t_ns;
        v_[n_ & mask_] = value;
        // Later samples at least as large make earlier smaller ones useless;
        // an equal earlier one stays in front (the earliest of a tie wins).
        while (tail_ > head_ && v_[dq_[(tail_ - 1) & mask_] & mask_] < value) --tail_;
        dq_[tail_++ & mask_] = n_;
        ++n_;
    }

    // End of stream: the remaining samples, judged on the window there is.
    template <class Out>
    void flush(Out&& out) {
        while (c_ < n_) judge(out);
    }

    void reset() { n_ = c_ = head_ = tail_ = 0; }

private:
    // Judges sample c_: every sample up to t_c + h is in the deque, none later.
    template <class Out>
    void judge(Out&& out) {
        const int64_t t = t_[c_ & mask_];
        while (tail_ > head_ && t_[dq_[head_ & mask_] & mask_] < t - h_ns_) ++head_;
        const bool peak = tail_ > head_ && dq_[head_ & mask_] == c_;
        out(t, v_[c_ & mask_], peak);
        ++c_;
    }

    int64_t h_ns_;
    uint64_t size_, mask_;
    std::vector<int64_t> t_;
    std::vector<double> v_;
    std::vector<uint64_t> dq_;  // sample numbers, values decreasing from head to tail
    uint64_t n_ = 0, c_ = 0, head_ = 0, tail_ = 0;
};

}  // namespace pednav::signal
