// SPDX-License-Identifier: Apache-2.0
// The majority vote: decisions, ties, and a centred five-sample majority
// filter with truncated windows at both ends.
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>

#include <pednav_signal/centred_window.hpp>
#include <pednav_signal/majority_vote.hpp>

using namespace pednav::signal;

TEST_CASE("majority of the window, the centre's own vote on a tie") {
    MajorityVote v;
    CHECK(v.decide(0, true));  // an empty window: the centre's own vote
    CHECK_FALSE(v.decide(0, false));
    v.add(true);
    v.add(false);
    CHECK(v.ones == 1);
    CHECK(v.decide(2, true));
    CHECK_FALSE(v.decide(2, false));
    v.add(true);
    CHECK(v.decide(3, false));  // 2 of 3
    v.remove(true);
    v.remove(true);
    CHECK(v.ones == 0);
    CHECK_FALSE(v.decide(1, true));  // 0 of 1
}

TEST_CASE("a centred five-sample majority filter removes isolated flips and keeps runs") {
    const std::vector<bool> in = {true, true, false, true, true, false, false, true, false, false};
    const std::vector<bool> expect = {true, true, true, true, false, true, false, false, false, false};
    const uint64_t size = 16, mask = size - 1;
    std::vector<int64_t> t_ring(size);
    std::vector<bool> votes(size);
    const int64_t h = 2000000;  // samples 1 ms apart: the centre and two on each side
    MajorityVote v;
    std::vector<bool> out;
    uint64_t n = 0, c = 0, hi = 0, lo = 0;
    const auto finish = [&] {
        slide_centred_window(
            t_ring.data(), mask, n, c, t_ring[c & mask], h, hi, lo,
            [&](uint64_t i) { v.add(votes[i & mask]); }, [&](uint64_t i) { v.remove(votes[i & mask]); });
        out.push_back(v.decide(static_cast<int64_t>(hi - lo), votes[c & mask]));
        ++c;
    };
    for (size_t k = 0; k < in.size(); ++k) {
        t_ring[n & mask] = static_cast<int64_t>(k) * 1000000;
        votes[n & mask] = in[k];
        ++n;
        while (c < n && t_ring[(n - 1) & mask] >= t_ring[c & mask] + h) finish();
    }
    while (c < n) finish();
    CHECK(out == expect);
}
