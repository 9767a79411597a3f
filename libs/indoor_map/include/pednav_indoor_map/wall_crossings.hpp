// SPDX-License-Identifier: Apache-2.0
// Where a track goes through walls: each step between two positions on the
// same floor that meets a wall of that floor. An output track of a map
// matcher should have none.
#pragma once

#include <cstddef>
#include <vector>

#include "map.hpp"

namespace pednav::indoor_map {

struct WallCrossing {
    size_t step;  // the step from track[step - 1] to track[step]
    int wall_feature;
};

// `floors[i]` is the floor of `track[i]` (empty: all on floor 0). Steps that
// change floor are not tested; a step touching a wall counts.
std::vector<WallCrossing> wall_crossings(const Map& map, const std::vector<Point2>& track,
                                         const std::vector<int>& floors);

}  // namespace pednav::indoor_map
