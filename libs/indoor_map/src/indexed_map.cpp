// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/indexed_map.hpp"

#include <algorithm>
#include <utility>

#include "pednav_indoor_map/geometry_2d.hpp"

namespace pednav::indoor_map {

bool connector_links(const Connector& c, int from, int to) {
    if (from == to) return false;
    const int lo = std::min(c.floor, c.floor_to), hi = std::max(c.floor, c.floor_to);
    if (c.kind == ConnectorKind::lift) {  // stops at every floor it passes
        if (from < lo || from > hi || to < lo || to > hi) return false;
    } else if (std::min(from, to) != lo || std::max(from, to) != hi) {  // stairs, escalators: end to end
        return false;
    }
    switch (c.direction) {
        case ConnectorDirection::up: return to > from;
        case ConnectorDirection::down: return to < from;
        case ConnectorDirection::both: return true;
    }
    return false;
}

bool near_connector(const Connector& c, const Point2& p) {
    if (c.area.empty()) return false;
    if (c.is_arrow) return distance_to_polyline(p, c.area) <= c.reach_m;
    if (c.area.size() >= 3 && point_in_ring(p, c.area)) return true;
    if (c.reach_m <= 0) return false;
    double d = distance_to_polyline(p, c.area);
    if (c.area.size() >= 3) d = std::min(d, distance_to_segment(p, c.area.back(), c.area.front()));
    return d <= c.reach_m;
}

Point2 connector_exit(const Connector& c, int to, const Point2& p) {
    if (!c.is_arrow || c.area.empty() || c.kind == ConnectorKind::stairs) return p;
    return to == c.floor_to ? c.area.back() : c.area.front();
}

IndexedMap::IndexedMap(Map m, double cell_m)
    : map(std::move(m)), walls(map.walls, cell_m), zones(map.zones, cell_m) {}

bool IndexedMap::has_link(int from, int to) const {
    for (const Connector& c : map.connectors)
        if (connector_links(c, from, to)) return true;
    return false;
}

}  // namespace pednav::indoor_map
