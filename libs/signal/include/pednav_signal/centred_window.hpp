// SPDX-License-Identifier: Apache-2.0
// Centred time windows over rings of time-stamped samples.
//
// A stream of samples is numbered 0, 1, 2, ... in arrival order and kept in
// rings indexed by sample number & mask (a ring's size is a power of two).
// The centred window of the sample c at time t holds every sample with
// |t_i - t| <= h (h = half the window); it is the range of sample numbers
// [lo, hi), moved forward by slide_centred_window() as the centre advances.
// Windows are in seconds, so they hold the same time span at any rate.
#pragma once

#include <cmath>
#include <cstdint>

namespace pednav::signal {

// Half of a window of window_s, in ns (rounded to the nearest ns).
inline int64_t half_window_ns(double window_s) {
    return static_cast<int64_t>(std::llround(window_s * 0.5e9));
}

// The smallest power of two that is at least n and at least 16: a ring size.
inline uint64_t ring_size_for(uint64_t n) {
    uint64_t size = 16;
    while (size < n) size <<= 1;
    return size;
}

// A ring size that holds a window of window_s at up to rate_hz samples per
// second, plus 64 samples of margin.
inline uint64_t ring_size_for_window(double window_s, double rate_hz) {
    return ring_size_for(static_cast<uint64_t>(std::ceil(window_s * rate_hz)) + 64);
}

// Moves the window [lo, hi) of centre c at time t to the samples within h of
// t: add(i) takes in each sample up to t + h (of the n pushed so far, times
// in the ring t_ring with `mask`), remove(i) drops each sample before t - h,
// never past the centre. Called for c = 0, 1, 2, ... in turn (the window only
// moves forward). hi and lo are passed by reference so that a caller can keep
// them in locals while add and remove store into rings.
template <class Add, class Remove>
inline void slide_centred_window(const int64_t* t_ring, uint64_t mask, uint64_t n, uint64_t c, int64_t t,
                                 int64_t h, uint64_t& hi, uint64_t& lo, Add&& add, Remove&& remove) {
    while (hi < n && t_ring[hi & mask] <= t + h) add(hi++);
    while (lo < c && t_ring[lo & mask] < t - h) remove(lo++);
}

}  // namespace pednav::signal
