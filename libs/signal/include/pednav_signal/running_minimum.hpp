// SPDX-License-Identifier: Apache-2.0
// The running minimum of a sliding window in O(1) amortised per sample: a
// monotone deque (Lemire 2006, "Streaming maximum-minimum filter using no
// more than three comparisons per element") of the sample numbers of the
// window's strict suffix minima, oldest first, so the front is the minimum.
// For a running maximum, push the negated values.
//
// The values stay in the caller's ring (indexed by sample number & mask,
// centred_window.hpp); the deque keeps only sample numbers, in a ring the
// caller owns of a power-of-two size at least the window's longest length.
// A RunningMinimum is a small value (the ring, its mask and two counters): a
// caller may work on a local copy and store back head and tail (the only
// fields that change), so that the counters stay in registers while the ring
// is written.
#pragma once

#include <cmath>
#include <cstdint>

namespace pednav::signal {

struct RunningMinimum {
    uint64_t* ring = nullptr;  // sample numbers, size mask + 1
    uint64_t mask = 0;
    uint64_t head = 0, tail = 0;  // the deque is ring[head..tail) (indices & mask)

    // Sample i enters the window at its newest end (values[i & values_mask]
    // is its value): every sample before it with a value >= it can no longer
    // be the minimum and leaves the deque.
    void push(uint64_t i, const double* values, uint64_t values_mask) {
        const double x = values[i & values_mask];
        while (tail > head && values[ring[(tail - 1) & mask] & values_mask] >= x) --tail;
        ring[tail++ & mask] = i;
    }

    // Sample i leaves the window at its oldest end.
    void pop(uint64_t i) {
        if (tail > head && ring[head & mask] == i) ++head;
    }

    // The smallest value in the window; +infinity for an empty window.
    double min(const double* values, uint64_t values_mask) const {
        return tail > head ? values[ring[head & mask] & values_mask] : HUGE_VAL;
    }
};

}  // namespace pednav::signal
