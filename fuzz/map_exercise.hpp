// SPDX-License-Identifier: Apache-2.0
// What the engine does with a pednav.map/1 document (docs/maps.md), for the
// map fuzz targets: its origin, the map read around it (the particle filter's
// load_map), the checks of `pednav map check`, the wall and zone index of the
// matcher (wall_cell_m 2 m, the default) and the wall crossings of a short
// track. A MapError is the expected answer to a bad document.
#pragma once

#include <string_view>

namespace pednav::fuzz {

void exercise_map(std::string_view document);

}  // namespace pednav::fuzz
