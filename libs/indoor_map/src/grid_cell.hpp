// SPDX-License-Identifier: Apache-2.0
// Internal: the cell side of the wall and zone grids (wall_index.cpp,
// zone_index.cpp) over a map's extent.
#pragma once

#include <cmath>
#include <cstddef>

namespace pednav::indoor_map::detail {

// Cells one floor's grid may have: 262 144, a floor of 1 km x 1 km at 2 m.
constexpr double kMaxGridCells = 262144.0;

// `cell_m`, doubled until a grid over extent_e_m x extent_n_m (m) has at most
// kMaxGridCells cells. A map kilometres wide, or one mistyped coordinate that
// puts a wall a degree away, then gets coarser cells instead of a grid of
// billions of cells built for minutes: the queries test each wall of a cell
// exactly, so only their speed changes, never their answer.
inline double grid_cell_m(double cell_m, double extent_e_m, double extent_n_m) {
    if (!std::isfinite(extent_e_m) || extent_e_m < 0) extent_e_m = 0;
    if (!std::isfinite(extent_n_m) || extent_n_m < 0) extent_n_m = 0;
    double c = cell_m;
    for (int i = 0; i < 2100 && (std::ceil(extent_e_m / c) + 2) * (std::ceil(extent_n_m / c) + 2) > kMaxGridCells; ++i)
        c *= 2.0;
    return c;
}

}  // namespace pednav::indoor_map::detail
