// SPDX-License-Identifier: Apache-2.0
// Centred time windows: half widths, ring sizes, and the window that
// slide_centred_window() keeps against the samples within h of each centre.
#include <doctest/doctest.h>

#include <cstdint>
#include <random>
#include <vector>

#include <pednav_signal/centred_window.hpp>

using namespace pednav::signal;

TEST_CASE("half windows in ns and ring sizes") {
    CHECK(half_window_ns(0.06) == 30000000);
    CHECK(half_window_ns(1.0) == 500000000);
    CHECK(half_window_ns(0.0) == 0);
    CHECK(half_window_ns(1e-9) == 1);  // half a ns rounds away from zero
    CHECK(ring_size_for(0) == 16);
    CHECK(ring_size_for(16) == 16);
    CHECK(ring_size_for(17) == 32);
    CHECK(ring_size_for(1025) == 2048);
    CHECK(ring_size_for_window(0.0, 1000.0) == 64);     // the margin alone
    CHECK(ring_size_for_window(0.06, 1000.0) == 128);   // 60 + 64
    CHECK(ring_size_for_window(0.05, 200.0) == 128);    // 10 + 64
    CHECK(ring_size_for_window(1.0, 1000.0) == 2048);   // 1000 + 64
    CHECK(ring_size_for_window(0.064, 1000.0) == 128);  // 64 + 64 fits exactly
}

namespace {
// Irregular times: about 200 Hz with jitter and two gaps.
std::vector<int64_t> irregular_times(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int64_t> jitter(-1500000, 1500000);
    std::vector<int64_t> t;
    int64_t now = 0;
    for (size_t k = 0; k < n; ++k) {
        now += 5000000 + jitter(rng);
        if (k == 300 || k == 301) now += 80000000;  // a logger's dropout
        t.push_back(now);
    }
    return t;
}
}  // namespace

TEST_CASE("the window of every centre holds exactly the samples within h of it, over a ring that wraps") {
    const std::vector<int64_t> t = irregular_times(1000, 3);
    const int64_t h = half_window_ns(0.06);
    const uint64_t size = ring_size_for_window(0.06, 400.0), mask = size - 1;  // far fewer than 1000 samples
    REQUIRE(size == 128);
    std::vector<int64_t> ring(size);
    uint64_t n = 0, c = 0, hi = 0, lo = 0;
    int64_t sum = 0;  // the sum of the sample numbers in the window, kept by add and remove
    uint64_t added = 0, removed = 0;
    int checked = 0, mismatches = 0;
    bool alone = false;
    const auto finish = [&](size_t pushed) {
        const int64_t tc = t[c];
        slide_centred_window(
            ring.data(), mask, n, c, tc, h, hi, lo,
            [&](uint64_t i) {
                CHECK(i == added++);
                sum += static_cast<int64_t>(i);
            },
            [&](uint64_t i) {
                CHECK(i == removed++);
                sum -= static_cast<int64_t>(i);
            });
        // Brute force over the samples pushed so far.
        uint64_t first = pushed, last = 0;
        int64_t expect_sum = 0;
        for (size_t j = 0; j < pushed; ++j)
            if (t[j] >= tc - h && t[j] <= tc + h) {
                first = std::min<uint64_t>(first, j);
                last = j + 1;
                expect_sum += static_cast<int64_t>(j);
            }
        mismatches += lo != first || hi != last || sum != expect_sum;
        if (c == 300) alone = lo == 300 && hi == 301;
        CHECK(lo <= c);
        CHECK(hi > c);
        ++checked;
        ++c;
    };
    for (size_t k = 0; k < t.size(); ++k) {
        ring[n & mask] = t[k];
        ++n;
        // A centre is final once the input has reached its time + h.
        while (c < n && t[k] >= t[c] + h) finish(n);
    }
    while (c < n) finish(n);  // end of stream: truncated windows
    CHECK(checked == 1000);
    CHECK(mismatches == 0);
    CHECK(added == 1000);
    CHECK(removed == lo);
    // Sample 300 sits between the two gaps of the dropout: alone in its window.
    CHECK(alone);
}
