// SPDX-License-Identifier: Apache-2.0
// The heights of the level floors a walk has stood on.
#include <doctest/doctest.h>

#include <pednav_zupt_ins/level_memory.hpp>

using namespace pednav::zupt_ins;

TEST_CASE("level memory: a floor reached again gets its first height back, a new one is remembered") {
    LevelMemory m(0.1);
    CHECK(m.arrive(0.0) == 0.0);   // start floor
    CHECK(m.arrive(1.52) == 1.52); // landing: new
    CHECK(m.arrive(3.05) == 3.05); // floor 1: new
    CHECK(m.size() == 3);
    CHECK(m.arrive(1.58) == 1.52); // the landing again, 6 cm off
    CHECK(m.arrive(-0.07) == 0.0); // the start floor again
    CHECK(m.arrive(0.17) == 0.17); // one riser above the start floor: another level
    CHECK(m.arrive(0.09) == 0.17); // nearest of the two within reach
    CHECK(m.size() == 4);
    LevelMemory off(0.0);
    CHECK(off.arrive(1.0) == 1.0);
    CHECK(off.arrive(1.0) == 1.0);
    CHECK(off.size() == 0);
}
