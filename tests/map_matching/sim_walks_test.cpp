// SPDX-License-Identifier: Apache-2.0
// Simulated multi-floor walks with their building map through the foot
// pipeline and the map matcher (issue 13: floor right >= 99 % of the time,
// IPIN score p75 < 1 m, no wall crossed by the output track, reproducible).
#include <doctest/doctest.h>

#include <cstring>
#include <cstdio>
#include <cstdlib>

#include "matched_walks.hpp"

using namespace pednav;
using namespace pednav::test;

namespace {

MatchedWalk foot_walk(const std::string& route, uint64_t seed) {
    MatchedWalk w;
    w.walk.route = route;
    w.walk.mount = "foot";
    w.walk.seed = seed;
    w.walk.with_baro = true;
    w.config_path = std::string(PEDNAV_SOURCE_DIR) + "/configs/foot.json";
    w.plugin_dir = PEDNAV_PLUGIN_OUTPUT_DIR;
    w.work_dir = PEDNAV_TEST_WORK_DIR;
    return w;
}

}  // namespace

TEST_CASE("issue 13: simulated multi-floor walks with their map, behind the foot pipeline") {
    for (const char* route : {"stairs", "building_tour"})
        for (uint64_t seed : {1, 2, 3}) {
            const MatchedWalkScore s = run_matched_walk(foot_walk(route, seed));
            MESSAGE(std::string(route) << " seed " << seed << ": floor right " << 100 * s.floor_right << " %, IPIN p75 "
                          << s.ipin_p75_m << " m, horizontal p75 " << s.horizontal_p75_m << " m (without the map "
                          << s.raw_p75_m << " m), max " << s.horizontal_max_m << " m, crossings " << s.crossings
                          << ", recoveries " << s.recoveries << ", fewest live particles " << s.min_live);
            if (std::getenv("MM_DUMP")) {
                FILE* f = std::fopen((std::string("/tmp/mm_") + route + std::to_string(seed) + ".csv").c_str(), "w");
                for (const auto& p : s.track) std::fprintf(f, "%.3f,%.3f,%.3f,%d,%u,%u\n", 1e-9 * p.header.t_ns, p.pos_enu_m[0], p.pos_enu_m[1], p.floor, p.live_particles, p.recoveries);
                std::fclose(f);
            }
            CHECK(s.floor_right >= 0.99);
            CHECK(s.ipin_p75_m < 1.0);
            CHECK(s.crossings == 0);
            CHECK(s.recoveries == 0);
        }
}
