// SPDX-License-Identifier: Apache-2.0
// Majority (binary median) filter over a sliding window of yes/no decisions:
// a running count of the yes votes in the window; the filtered decision of
// the window's centre is the majority, or the centre's own decision on a tie
// (an even count).
#pragma once

#include <cstdint>

namespace pednav::signal {

struct MajorityVote {
    int64_t ones = 0;  // yes votes in the window

    void add(bool vote) { ones += vote; }
    void remove(bool vote) { ones -= vote; }

    // The decision of a centre whose own vote is `centre`, over a window of
    // `count` votes.
    bool decide(int64_t count, bool centre) const {
        if (2 * ones > count) return true;
        if (2 * ones < count) return false;
        return centre;
    }
};

}  // namespace pednav::signal
