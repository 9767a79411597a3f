// SPDX-License-Identifier: Apache-2.0
// The humolire-phone walks through the handheld preset with the map matcher
// on their converted map, from the given start point and heading: error at
// the landmark times with and without the map, wall crossings of the output.
#include <doctest/doctest.h>

#include <pednav_eval/walks.hpp>

#include "matched_recordings.hpp"

using namespace pednav;

// Measured bounds: the p75 under 1.5 m on every walk is reached on
// user1_square_2x only. The map helps where its walls bound the walk
// (user1_square_2x, user1_8_shape, user3_forward) and cannot correct the
// along-track error of the straight walk (user1_straight, a long corridor).
TEST_CASE("humolire-phone walks on their converted map, handheld preset, error at the landmarks") {
    struct Bound {
        const char* walk;
        double p75_max_m;
    };
    for (const Bound& b : {Bound{"user1_straight", 7.5}, Bound{"user1_8_shape", 2.2}, Bound{"user1_square_2x", 1.2},
                           Bound{"user3_forward", 4.8}}) {
        const std::string walk = b.walk;
        const test::MatchedRecordingScore s =
            test::run_humolire_walk(PEDNAV_SHARED_DATA_DIR, walk, std::string(PEDNAV_SOURCE_DIR) + "/configs/handheld.json",
                                    PEDNAV_PLUGIN_OUTPUT_DIR, PEDNAV_TEST_WORK_DIR);
        MESSAGE(walk << ": with the map mean " << s.with_map.mean << " median " << s.with_map.median << " p75 "
                     << s.with_map.p75 << " max " << s.with_map.max << " m; without mean " << s.without_map.mean
                     << " median " << s.without_map.median << " p75 " << s.without_map.p75 << " max "
                     << s.without_map.max << " m; crossings " << s.crossings << ", recoveries " << s.recoveries
                     << ", fewest live " << s.min_live << ", positions " << s.positions);
        CHECK(s.with_map.p75 < b.p75_max_m);
        CHECK(s.crossings == 0);
        CHECK(s.recoveries == 0);
    }
}

