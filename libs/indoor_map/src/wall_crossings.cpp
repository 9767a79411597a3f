// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/wall_crossings.hpp"

#include <algorithm>
#include <cmath>

#include "pednav_indoor_map/geometry_2d.hpp"

namespace pednav::indoor_map {

std::vector<WallCrossing> wall_crossings(const Map& map, const std::vector<Point2>& track,
                                         const std::vector<int>& floors) {
    auto floor_of = [&](size_t i) { return i < floors.size() ? floors[i] : 0; };
    std::vector<WallCrossing> out;
    for (size_t i = 1; i < track.size(); ++i) {
        if (floor_of(i) != floor_of(i - 1)) continue;
        const Point2 &a = track[i - 1], &b = track[i];
        if (!std::isfinite(a.e_m) || !std::isfinite(a.n_m) || !std::isfinite(b.e_m) || !std::isfinite(b.n_m)) continue;
        const double e0 = std::min(a.e_m, b.e_m), e1 = std::max(a.e_m, b.e_m);
        const double n0 = std::min(a.n_m, b.n_m), n1 = std::max(a.n_m, b.n_m);
        for (const WallSegment& w : map.walls) {
            if (w.floor != floor_of(i)) continue;
            // Boxes apart: no meeting (most walls of a building are far from a step).
            if (std::max(w.a.e_m, w.b.e_m) < e0 || std::min(w.a.e_m, w.b.e_m) > e1 ||
                std::max(w.a.n_m, w.b.n_m) < n0 || std::min(w.a.n_m, w.b.n_m) > n1)
                continue;
            if (segments_intersect(a, b, w.a, w.b)) out.push_back({i, w.feature});
        }
    }
    return out;
}

}  // namespace pednav::indoor_map
