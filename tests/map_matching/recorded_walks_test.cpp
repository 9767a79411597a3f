// SPDX-License-Identifier: Apache-2.0
// The humolire-phone walks through the handheld preset with the map matcher
// on their converted map, from the given start point and heading: error at
// the landmark times with and without the map, wall crossings of the output.
// The biba-chest-xsens routes through the chest preset on theirs.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>

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


// biba-chest-xsens has no truth (its SOURCE.md): a plumbing and robustness
// check on its map. core.txt's scale (0.33167 m per pixel) makes the
// corridors 5.8 m wide and the floor 577 m x 286 m; at 0.115 m per pixel
// the corridors (walls 17-18 px apart) are 2.0 m wide, and the two routes,
// one the way back of the other, meet: rita_to_kar from core.txt's start
// ends at the same point whatever its start heading within 60 deg, and
// kar_to_rita started there comes back to core.txt's start within a metre
// from any start heading within 80 deg (docs/map-matcher.md). Neither crosses
// a wall or loses its cloud. The start headings are not in the data.
TEST_CASE("biba-chest-xsens: both routes on the map at 0.115 m per pixel, the way there and back meet") {
    constexpr double kScaleMPerPx = 0.115;
    const std::string preset = std::string(PEDNAV_SOURCE_DIR) + "/configs/chest.json";
    auto run = [&](const char* route, double e, double n, double heading_deg) {
        test::BibaRun r;
        r.route = route;
        r.scale_m_per_px = kScaleMPerPx;
        r.start_enu_m[0] = e;
        r.start_enu_m[1] = n;
        r.heading_deg = heading_deg;
        const test::BibaScore b = test::run_biba_route(PEDNAV_SHARED_DATA_DIR, r, preset,
                                                       PEDNAV_PLUGIN_OUTPUT_DIR, PEDNAV_TEST_WORK_DIR);
        MESSAGE(std::string(route) << " from (" << e << ", " << n << ") heading " << heading_deg << ": ends at ("
                      << b.end_enu_m[0] << ", " << b.end_enu_m[1] << "), " << b.distance_m << " m, crossings "
                      << b.matched.crossings << ", recoveries " << b.matched.recoveries << ", fewest live "
                      << b.matched.min_live);
        CHECK(b.matched.crossings == 0);
        CHECK(b.matched.recoveries == 0);
        CHECK(b.matched.positions > 150);  // a step each: 167 steps on either route
        CHECK(b.distance_m > 100.0);       // the output walks the route (the steps sum to 135 m) ...
        CHECK(b.distance_m < 140.0);       // ... without jumping about
        return b;
    };
    std::vector<std::array<double, 2>> ends;
    for (double h : {170.0, 190.0, 210.0}) {
        const test::BibaScore b = run("rita_to_kar", 0.0, 0.0, h);
        ends.push_back({b.end_enu_m[0], b.end_enu_m[1]});
    }
    double there[2] = {0.0, 0.0};
    for (const auto& e : ends) {
        there[0] += e[0] / 3.0;
        there[1] += e[1] / 3.0;
    }
    for (const auto& e : ends) CHECK(std::hypot(e[0] - there[0], e[1] - there[1]) < 1.0);
    CHECK(std::hypot(there[0], there[1]) > 50.0);  // the offices are apart
    for (double h : {210.0, 230.0, 250.0}) {
        const test::BibaScore b = run("kar_to_rita", there[0], there[1], h);
        CHECK(std::hypot(b.end_enu_m[0], b.end_enu_m[1]) < 1.5);
    }
}
