// SPDX-License-Identifier: Apache-2.0
// Internal: the k-th smallest of a sequence read back in passes (a
// SpillVector), exactly the value std::nth_element finds on all of it, in
// memory independent of its length: short sequences are sorted in memory;
// long ones are narrowed down 16 bits of the value at a time (a radix
// selection on the bit pattern, which orders doubles as < does) until the
// few values left fit in memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace pednav::io::detail {

// Values at most this many are selected in memory.
constexpr size_t kInMemorySelection = size_t{1} << 16;

// An unsigned key ordered as the doubles are (-0 before +0).
inline uint64_t order_key(double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    return (bits >> 63) != 0 ? ~bits : bits | (uint64_t{1} << 63);
}

inline double from_order_key(uint64_t key) {
    const uint64_t bits = (key >> 63) != 0 ? key & ~(uint64_t{1} << 63) : ~key;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

// The k-th smallest (0-based, k < n) of the n values that for_each(f) passes to f
// in every pass; for_each must give the same values each time.
template <typename ForEach>
double kth_smallest(size_t n, size_t k, ForEach&& for_each) {
    std::vector<double> kept;
    uint64_t prefix = 0;  // the top `fixed` bits of the key sought
    int fixed = 0;
    size_t candidates = n;
    for (;;) {
        const uint64_t mask = fixed == 0 ? 0 : ~uint64_t{0} << (64 - fixed);
        const uint64_t want = fixed == 0 ? 0 : prefix << (64 - fixed);
        if (candidates <= kInMemorySelection) {
            kept.reserve(candidates);
            for_each([&](double v) {
                if ((order_key(v) & mask) == want) kept.push_back(v);
            });
            std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(k), kept.end());
            return kept[k];
        }
        std::vector<size_t> count(size_t{1} << 16, 0);
        const int shift = 48 - fixed;
        for_each([&](double v) {
            const uint64_t key = order_key(v);
            if ((key & mask) == want) ++count[(key >> shift) & 0xffff];
        });
        size_t bucket = 0;
        while (k >= count[bucket]) k -= count[bucket++];
        prefix = (prefix << 16) | bucket;
        fixed += 16;
        candidates = count[bucket];
        if (fixed == 64) return from_order_key(prefix);
    }
}

}  // namespace pednav::io::detail
