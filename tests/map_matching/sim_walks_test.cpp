// SPDX-License-Identifier: Apache-2.0
// Simulated multi-floor walks with their building map through the foot
// pipeline and the map matcher (issue 13: floor right >= 99 % of the time,
// IPIN score p75 < 1 m, no wall crossed by the output track, reproducible).
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>

#include "matched_walks.hpp"

using namespace pednav;
using namespace pednav::test;

namespace {

MatchedWalk mount_walk(const std::string& mount, const std::string& route, uint64_t seed) {
    MatchedWalk w;
    w.walk.route = route;
    w.walk.mount = mount;
    w.walk.seed = seed;
    w.walk.with_baro = true;
    w.config_path = std::string(PEDNAV_SOURCE_DIR) + "/configs/" + mount + ".json";
    w.plugin_dir = PEDNAV_PLUGIN_OUTPUT_DIR;
    w.work_dir = PEDNAV_TEST_WORK_DIR;
    return w;
}
MatchedWalk foot_walk(const std::string& route, uint64_t seed) { return mount_walk("foot", route, seed); }

}  // namespace

TEST_CASE("issue 13: simulated multi-floor walks with their map, behind the foot pipeline") {
    for (const char* route : {"stairs", "building_tour"})
        for (uint64_t seed : {1, 2, 3}) {
            const MatchedWalkScore s = run_matched_walk(foot_walk(route, seed));
            MESSAGE(std::string(route) << " seed " << seed << ": floor right " << 100 * s.floor_right << " %, IPIN p75 "
                          << s.ipin_p75_m << " m, horizontal p75 " << s.horizontal_p75_m << " m (without the map "
                          << s.raw_p75_m << " m), max " << s.horizontal_max_m << " m, crossings " << s.crossings
                          << ", recoveries " << s.recoveries << ", fewest live particles " << s.min_live);
            CHECK(s.floor_right >= 0.99);
            CHECK(s.ipin_p75_m < 1.0);
            CHECK(s.crossings == 0);
            CHECK(s.recoveries == 0);
        }
}

// Behind the chest and handheld step models, whose tracks are 2.3-10 m off
// without the map: the targets (floor right 99 %, IPIN p75 under
// 1 m), measured 99.89-100 % and 0.53-0.90 m (docs/map-matcher.md; seeds 3-5,
// not run here, 99.89-100 % and 0.42-0.92 m).
TEST_CASE("simulated multi-floor walks with their map, behind the chest and handheld pipelines") {
    struct Bound {
        const char *mount, *route;
    };
    for (const Bound& b : {Bound{"chest", "stairs"}, Bound{"chest", "building_tour"}, Bound{"handheld", "stairs"},
                           Bound{"handheld", "building_tour"}})
        for (uint64_t seed : {1, 2}) {
            const MatchedWalkScore s = run_matched_walk(mount_walk(b.mount, b.route, seed));
            MESSAGE(std::string(b.mount) << " " << std::string(b.route) << " seed " << seed << ": floor right " << 100 * s.floor_right
                            << " %, IPIN p75 " << s.ipin_p75_m << " m, horizontal p75 " << s.horizontal_p75_m
                            << " m (without the map " << s.raw_p75_m << " m), max " << s.horizontal_max_m
                            << " m, crossings " << s.crossings << ", recoveries " << s.recoveries
                            << ", fewest live particles " << s.min_live);
            CHECK(s.floor_right >= 0.99);
            CHECK(s.ipin_p75_m < 1.0);
            CHECK(s.horizontal_p75_m < s.raw_p75_m);
            CHECK(s.crossings == 0);
            CHECK(s.recoveries == 0);
        }
}

TEST_CASE("the output track crosses no wall with wider step scales either (a slide round a corner is checked as the straight step it is)") {
    // With these settings the chest tour once had an output step that slid
    // along one wall and cut the corner of another.
    MatchedWalk w = mount_walk("chest", "building_tour", 1);
    w.matcher_params = {{"scale_min", 0.8}, {"scale_max", 1.2}};
    const MatchedWalkScore s = run_matched_walk(w);
    MESSAGE("chest building_tour, scales 0.8-1.2: horizontal p75 " << s.horizontal_p75_m << " m");
    CHECK(s.crossings == 0);
    CHECK(s.recoveries == 0);
    CHECK(s.horizontal_p75_m < 0.7);  // measured 0.56 m (0.75 m while the simulated steps read short)
}

TEST_CASE("the same seed gives the same track bit for bit, another seed another track as good") {
    MatchedWalk w = foot_walk("stairs", 1);
    const MatchedWalkScore a = run_matched_walk(w), b = run_matched_walk(w);
    REQUIRE(a.track.size() == b.track.size());
    size_t differing = 0;
    for (size_t i = 0; i < a.track.size(); ++i)
        differing += std::memcmp(&a.track[i], &b.track[i], sizeof(pn_position_t)) != 0;
    CHECK(differing == 0);
    w.matcher_params = {{"seed", 99}};
    const MatchedWalkScore c = run_matched_walk(w);
    REQUIRE(c.track.size() == a.track.size());
    differing = 0;
    for (size_t i = 0; i < a.track.size(); ++i) differing += a.track[i].pos_enu_m[0] != c.track[i].pos_enu_m[0];
    CHECK(differing > a.track.size() / 2);
    CHECK(c.ipin_p75_m < 1.0);
    CHECK(c.crossings == 0);
}

TEST_CASE("recovery: started 15 m off, inside the block the ring corridor goes round, the cloud dies and is reseeded") {
    // The start point given to the engine is (30, 15) for a walk that starts
    // at (0, 0): every step of the track leads into the block's walls.
    MatchedWalk w = foot_walk("building_tour", 1);
    w.start_offset_m[0] = 30.0;
    w.start_offset_m[1] = 15.0;
    const MatchedWalkScore s = run_matched_walk(w);
    MESSAGE("started off: recoveries " << s.recoveries << ", recovered outputs " << s.recovered_flags
                                       << ", horizontal p75 " << s.horizontal_p75_m << " m");
    CHECK(s.recoveries >= 1);
    CHECK(s.recovered_flags == s.recoveries);  // each recovery flags the position after it
    CHECK(s.describe_json.find("every particle died") != std::string::npos);
    // Never frozen: the output keeps moving over the whole walk.
    double moved = 0;
    for (size_t i = 1; i < s.track.size(); ++i)
        moved += std::hypot(s.track[i].pos_enu_m[0] - s.track[i - 1].pos_enu_m[0],
                            s.track[i].pos_enu_m[1] - s.track[i - 1].pos_enu_m[1]);
    CHECK(moved > 400.0);  // of 614 m walked
    // No survivors only from a recovery to the next step.
    bool after_recovery = false;
    for (size_t i = 0; i < s.track.size(); ++i) {
        const pn_position_t& p = s.track[i];
        REQUIRE(std::isfinite(p.pos_enu_m[0]));
        if (p.header.flags & PN_POSITION_FLAG_RECOVERED) after_recovery = true;
        else if (p.live_particles > 0) after_recovery = false;
        if (p.live_particles == 0) REQUIRE(after_recovery);
    }
}
