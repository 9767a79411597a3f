// SPDX-License-Identifier: Apache-2.0
// The running minimum against the minimum of each window recomputed anew.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <pednav_signal/centred_window.hpp>
#include <pednav_signal/running_minimum.hpp>

using namespace pednav::signal;

namespace {
// A centred running minimum over a stream: times t, values v (each pushed
// in turn, centres finished once the input reaches their time + h, the rest
// at the end); `negate` gives the running maximum instead.
struct Driven {
    std::vector<double> minima;
    uint64_t longest_deque = 0;
};
Driven run(const std::vector<int64_t>& t, const std::vector<double>& v, int64_t h, uint64_t size,
           bool negate) {
    const uint64_t mask = size - 1;
    std::vector<int64_t> t_ring(size);
    std::vector<double> v_ring(size);
    std::vector<uint64_t> deque(size);
    RunningMinimum m;
    m.ring = deque.data();
    m.mask = mask;
    Driven out;
    uint64_t n = 0, c = 0, hi = 0, lo = 0;
    const auto finish = [&] {
        slide_centred_window(
            t_ring.data(), mask, n, c, t_ring[c & mask], h, hi, lo,
            [&](uint64_t i) { m.push(i, v_ring.data(), mask); }, [&](uint64_t i) { m.pop(i); });
        out.longest_deque = std::max(out.longest_deque, m.tail - m.head);
        const double x = m.min(v_ring.data(), mask);
        out.minima.push_back(negate ? -x : x);
        ++c;
    };
    for (size_t k = 0; k < t.size(); ++k) {
        t_ring[n & mask] = t[k];
        v_ring[n & mask] = negate ? -v[k] : v[k];
        ++n;
        while (c < n && t[k] >= t_ring[c & mask] + h) finish();
    }
    while (c < n) finish();
    return out;
}
}  // namespace

TEST_CASE("running minimum and maximum equal the window's own, with ties, at irregular times") {
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> digit(0, 9);  // few distinct values: many ties
    std::uniform_int_distribution<int64_t> dt(2000000, 8000000);
    std::vector<int64_t> t;
    std::vector<double> v;
    int64_t now = 0;
    for (int k = 0; k < 3000; ++k) {
        now += dt(rng);
        t.push_back(now);
        v.push_back(0.5 * digit(rng) - 1.0);
    }
    const int64_t h = half_window_ns(0.5);  // about 100 samples
    const uint64_t size = ring_size_for_window(0.5, 500.0);
    REQUIRE(size == 512);
    const Driven mins = run(t, v, h, size, false), maxs = run(t, v, h, size, true);
    REQUIRE(mins.minima.size() == t.size());
    REQUIRE(maxs.minima.size() == t.size());
    int wrong = 0;
    double lowest = HUGE_VAL;
    for (size_t c = 0; c < t.size(); ++c) {
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (size_t j = 0; j < t.size(); ++j)
            if (std::llabs(t[j] - t[c]) <= h) {
                lo = std::min(lo, v[j]);
                hi = std::max(hi, v[j]);
            }
        wrong += mins.minima[c] != lo || maxs.minima[c] != hi;
        lowest = std::min(lowest, lo);
    }
    CHECK(wrong == 0);
    CHECK(lowest == -1.0);
    // Strict suffix minima of ten distinct values: never more than ten.
    CHECK(mins.longest_deque <= 10);
    CHECK(mins.longest_deque >= 2);
}

TEST_CASE("the deque holds the strict suffix minima: all of a rising run, one of a falling or flat one") {
    const uint64_t size = 16, mask = size - 1;
    std::vector<uint64_t> deque(size);
    const double rising[5] = {1, 2, 3, 4, 5}, falling[5] = {5, 4, 3, 2, 1}, flat[5] = {2, 2, 2, 2, 2};
    for (const double* values : {rising, falling, flat}) {
        RunningMinimum m;
        m.ring = deque.data();
        m.mask = mask;
        CHECK(m.min(values, 15) == HUGE_VAL);  // empty window
        for (uint64_t i = 0; i < 5; ++i) m.push(i, values, 15);
        CHECK(m.min(values, 15) == std::min({values[0], values[4]}));
        const uint64_t held = m.tail - m.head;
        CHECK(held == (values == rising ? 5u : 1u));
        // The oldest sample leaves: only a rising run loses its minimum.
        m.pop(0);
        CHECK(m.min(values, 15) == (values == rising ? 2.0 : values[4]));
    }
}
