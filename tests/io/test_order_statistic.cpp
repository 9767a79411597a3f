// SPDX-License-Identifier: Apache-2.0
// The reader's internal sequences too long to hold: SpillVector reads back
// what it wrote to its temporary file, and kth_smallest finds what
// std::nth_element finds, down to the last bit, on sequences long enough for
// its radix passes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "order_statistic.hpp"
#include "spill_vector.hpp"

using namespace pednav::io::detail;

TEST_CASE("SpillVector: 100 000 values in blocks of 1 000 come back in order") {
    SpillVector<uint64_t> v(1000);
    for (uint64_t i = 0; i < 100000; ++i) v.push_back(i * 3 + 1);
    CHECK(v.size() == 100000);
    CHECK(v.front() == 1);
    CHECK(v.back() == 299998);
    uint64_t expected = 1, wrong = 0, seen = 0;
    v.for_each([&](uint64_t x) {
        wrong += x != expected ? 1 : 0;
        expected += 3;
        ++seen;
    });
    CHECK(seen == 100000);
    CHECK(wrong == 0);
}

TEST_CASE("kth_smallest equals nth_element on 300 000 doubles, spilled or not") {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> gauss(0.01, 0.002);
    std::vector<double> values(300000);
    for (size_t i = 0; i < values.size(); ++i) {
        values[i] = gauss(rng);
        if (i % 10 == 0) values[i] = -values[i];         // negative values
        if (i % 7 == 0) values[i] = 0.0100000000000001;  // many equal values
    }
    SpillVector<double> spilled(4096);
    for (double x : values) spilled.push_back(x);
    for (size_t k : {size_t{0}, size_t{1}, size_t{150000}, size_t{297000}, size_t{299999}}) {
        std::vector<double> sorted = values;
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(k), sorted.end());
        CAPTURE(k);
        CHECK(kth_smallest(values.size(), k, [&](auto&& f) {
                  for (double x : values) f(x);
              }) == sorted[k]);
        CHECK(kth_smallest(spilled.size(), k, [&](auto&& f) { spilled.for_each(f); }) == sorted[k]);
    }
    CHECK(from_order_key(order_key(-0.0)) == 0.0);
    CHECK(order_key(-1.0) < order_key(-0.5));
    CHECK(order_key(-0.5) < order_key(0.25));
    CHECK(order_key(0.25) < order_key(3.0));
}
