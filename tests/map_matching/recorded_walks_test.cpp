// SPDX-License-Identifier: Apache-2.0
// The humolire-phone walks through the handheld preset with the map matcher
// on their converted map, from the given start point and heading: error at
// the landmark times with and without the map, wall crossings of the output.
#include <doctest/doctest.h>

#include <pednav_eval/walks.hpp>

#include "matched_recordings.hpp"

using namespace pednav;

// The target, p75 under 1.5 m on every walk, and the measured
// bounds (docs/map-matcher.md): p75 0.71 / 0.87 / 1.00 / 1.12 m with the
// walkers' heights given (participant.txt), as an app knows its user's.
TEST_CASE("humolire-phone walks on their converted map, handheld preset, error at the landmarks") {
    struct Bound {
        const char* walk;
        double p75_max_m;
    };
    for (const Bound& b : {Bound{"user1_straight", 0.85}, Bound{"user1_8_shape", 1.0}, Bound{"user1_square_2x", 1.15},
                           Bound{"user3_forward", 1.3}}) {
        const std::string walk = b.walk;
        const test::MatchedRecordingScore s =
            test::run_humolire_walk(PEDNAV_SHARED_DATA_DIR, walk, std::string(PEDNAV_SOURCE_DIR) + "/configs/handheld.json",
                                    PEDNAV_PLUGIN_OUTPUT_DIR, PEDNAV_TEST_WORK_DIR);
        MESSAGE(walk << ": with the map mean " << s.with_map.mean << " median " << s.with_map.median << " p75 "
                     << s.with_map.p75 << " max " << s.with_map.max << " m; without mean " << s.without_map.mean
                     << " median " << s.without_map.median << " p75 " << s.without_map.p75 << " max "
                     << s.without_map.max << " m; crossings " << s.crossings << ", recoveries " << s.recoveries
                     << ", fewest live " << s.min_live << ", positions " << s.positions);
        CHECK(s.with_map.p75 < 1.5);
        CHECK(s.with_map.p75 < b.p75_max_m);
        CHECK(s.with_map.p75 < s.without_map.p75);
        CHECK(s.crossings == 0);
        CHECK(s.recoveries == 0);
    }
}

