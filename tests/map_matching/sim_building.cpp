// SPDX-License-Identifier: Apache-2.0
#include "sim_building.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>
#include <pednav_indoor_map/geometry_2d.hpp>

namespace pednav::test {

using indoor_map::Point2;
using indoor_map::WallSegment;

namespace {

int floor_of(double z_m, double floor_height_m) { return static_cast<int>(std::lround(z_m / floor_height_m)); }
bool at_floor_level(double z_m, double h) { return std::abs(z_m - floor_of(z_m, h) * h) < 1e-6; }

// Where along wall [a, b] (0..1) segment [p, q] crosses it, NaN when it does not.
double crossing_on_wall(const Point2& a, const Point2& b, const Point2& p, const Point2& q) {
    if (!indoor_map::segments_intersect(a, b, p, q)) return NAN;
    const double rx = b.e_m - a.e_m, ry = b.n_m - a.n_m, sx = q.e_m - p.e_m, sy = q.n_m - p.n_m;
    const double den = rx * sy - ry * sx;
    if (std::abs(den) < 1e-12) return NAN;  // along the wall: no door to cut
    return ((p.e_m - a.e_m) * sy - (p.n_m - a.n_m) * sx) / den;
}

// Cuts a door of width w centred where [p, q] crosses each wall of `floor`.
void cut_doors(std::vector<WallSegment>& walls, int floor, const Point2& p, const Point2& q, double w) {
    std::vector<WallSegment> out;
    for (const WallSegment& s : walls) {
        const double u = s.floor == floor ? crossing_on_wall(s.a, s.b, p, q) : NAN;
        if (std::isnan(u)) {
            out.push_back(s);
            continue;
        }
        const double len = std::hypot(s.b.e_m - s.a.e_m, s.b.n_m - s.a.n_m);
        const double u0 = u - 0.5 * w / len, u1 = u + 0.5 * w / len;
        auto at = [&](double t) { return Point2{s.a.e_m + t * (s.b.e_m - s.a.e_m), s.a.n_m + t * (s.b.n_m - s.a.n_m)}; };
        if (u0 > 0) out.push_back({s.a, at(u0), s.floor, s.feature});
        if (u1 < 1) out.push_back({at(u1), s.b, s.floor, s.feature});
    }
    walls.swap(out);
}

}  // namespace

indoor_map::Map sim_building_map(const sim::Route& route, const SimBuildingOptions& o) {
    const double h = route.floor_height_m;
    indoor_map::Map m;
    m.floor_height_m = h;
    int feature = 0;
    std::set<int> floors;
    for (const sim::Wall& w : route.walls) {
        for (size_t i = 0; i + 1 < w.points_enu_m.size(); ++i)
            m.walls.push_back({{w.points_enu_m[i][0], w.points_enu_m[i][1]},
                               {w.points_enu_m[i + 1][0], w.points_enu_m[i + 1][1]},
                               w.floor,
                               feature});
        floors.insert(w.floor);
        ++feature;
    }
    const auto& wp = route.waypoints;
    for (size_t i = 1; i < wp.size(); ++i) {
        const Point2 p{wp[i - 1].enu_m[0], wp[i - 1].enu_m[1]}, q{wp[i].enu_m[0], wp[i].enu_m[1]};
        for (int f : {floor_of(wp[i - 1].enu_m[2], h), floor_of(wp[i].enu_m[2], h)}) cut_doors(m.walls, f, p, q, o.door_width_m);
    }
    // A flight: the waypoints from one at a floor's level to the next at
    // another floor's level.
    for (size_t i = 0; i < wp.size();) {
        size_t j = i + 1;
        if (!at_floor_level(wp[i].enu_m[2], h)) {
            ++i;
            continue;
        }
        while (j < wp.size() && !at_floor_level(wp[j].enu_m[2], h)) ++j;
        if (j >= wp.size()) break;
        const int f0 = floor_of(wp[i].enu_m[2], h), f1 = floor_of(wp[j].enu_m[2], h);
        if (f0 != f1) {
            double e0 = INFINITY, n0 = INFINITY, e1 = -INFINITY, n1 = -INFINITY;
            for (size_t k = i; k <= j; ++k) {
                e0 = std::min(e0, wp[k].enu_m[0]);
                e1 = std::max(e1, wp[k].enu_m[0]);
                n0 = std::min(n0, wp[k].enu_m[1]);
                n1 = std::max(n1, wp[k].enu_m[1]);
            }
            const double g = o.stairs_margin_m;
            m.connectors.push_back({indoor_map::ConnectorKind::stairs, indoor_map::ConnectorDirection::both,
                                    std::min(f0, f1), std::max(f0, f1), false,
                                    {{e0 - g, n0 - g}, {e1 + g, n0 - g}, {e1 + g, n1 + g}, {e0 - g, n1 + g}}, 0.0,
                                    feature++});
            floors.insert(f0);
            floors.insert(f1);
            // Altitude-update zones around the stairs' foot and head, at
            // their floors' heights (the paper's arrows lie in such zones).
            const double z = o.altitude_zone_margin_m;
            for (int f : {f0, f1})
                m.zones.push_back({indoor_map::ZoneKind::altitude, f,
                                   {{{e0 - z, n0 - z}, {e1 + z, n0 - z}, {e1 + z, n1 + z}, {e0 - z, n1 + z}}},
                                   f * h, feature++});
        }
        i = j;
    }
    m.floors.assign(floors.begin(), floors.end());
    return m;
}

std::string map_to_geojson(const indoor_map::Map& m) {
    using nlohmann::json;
    json features = json::array();
    for (const WallSegment& w : m.walls)
        features.push_back({{"type", "Feature"},
                            {"properties", {{"pednav:kind", "wall"}, {"pednav:floor", w.floor}}},
                            {"geometry", {{"type", "LineString"},
                                          {"coordinates", {{w.a.e_m, w.a.n_m}, {w.b.e_m, w.b.n_m}}}}}});
    for (const indoor_map::Connector& c : m.connectors) {
        json ring = json::array();
        for (const Point2& p : c.area) ring.push_back({p.e_m, p.n_m});
        ring.push_back({c.area.front().e_m, c.area.front().n_m});
        features.push_back({{"type", "Feature"},
                            {"properties", {{"pednav:kind", "stairs"}, {"pednav:floor", c.floor}, {"pednav:floor_to", c.floor_to}}},
                            {"geometry", {{"type", "Polygon"}, {"coordinates", json::array({ring})}}}});
    }
    for (const indoor_map::Zone& z : m.zones) {
        json rings = json::array();
        for (const auto& r : z.rings) {
            json ring = json::array();
            for (const Point2& p : r) ring.push_back({p.e_m, p.n_m});
            ring.push_back({r.front().e_m, r.front().n_m});
            rings.push_back(ring);
        }
        const char* kind = z.kind == indoor_map::ZoneKind::altitude       ? "altitude_zone"
                           : z.kind == indoor_map::ZoneKind::no_particles ? "no_particles"
                                                                          : "zone";
        json props = {{"pednav:kind", kind}, {"pednav:floor", z.floor}};
        if (z.kind == indoor_map::ZoneKind::altitude) props["pednav:height_m"] = z.height_m;
        features.push_back(
            {{"type", "Feature"}, {"properties", props}, {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}});
    }
    json doc = {{"type", "FeatureCollection"}, {"pednav:crs", "local-enu"}, {"features", features}};
    if (std::isfinite(m.floor_height_m)) doc["pednav:floor_height_m"] = m.floor_height_m;
    return doc.dump();
}

}  // namespace pednav::test
