// SPDX-License-Identifier: Apache-2.0
// Which zone a point is in, per floor, through a uniform grid: each cell
// lists the zones whose bounding box overlaps it, so a lookup tests the
// polygons of one cell only. Built once per map; lookups allocate nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "map.hpp"

namespace pednav::indoor_map {

class ZoneIndex {
public:
    ZoneIndex() = default;
    // Keeps a copy of the zones. cell_m: grid cell side, m (> 0); throws
    // std::invalid_argument otherwise.
    ZoneIndex(const std::vector<Zone>& zones, double cell_m);

    // The first zone of `kind` on `floor` that contains p (point_in_polygon),
    // or nullptr.
    const Zone* zone_at(int floor, const Point2& p, ZoneKind kind) const;
    bool in_zone(int floor, const Point2& p, ZoneKind kind) const { return zone_at(floor, p, kind) != nullptr; }
    // Whether the map has any zone of this kind on this floor.
    bool has_kind(int floor, ZoneKind kind) const;
    // The cell side in use: the one asked for, or wider over a very large map.
    double cell_m() const { return cell_m_; }

    const std::vector<Zone>& zones() const { return zones_; }

private:
    struct FloorGrid {
        int floor = 0;
        double e0 = 0, n0 = 0;
        int cols = 0, rows = 0;
        std::vector<uint32_t> cell_begin;  // rows * cols + 1 offsets into cell_zones
        std::vector<uint32_t> cell_zones;  // indices into zones_
        uint32_t kinds = 0;                // bit per ZoneKind present
    };
    std::vector<Zone> zones_;
    std::vector<FloorGrid> floors_;
    double cell_m_ = 1.0;
};

}  // namespace pednav::indoor_map
