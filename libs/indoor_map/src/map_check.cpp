// SPDX-License-Identifier: Apache-2.0
#include "pednav_indoor_map/map_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "geojson_document.hpp"
#include "pednav_indoor_map/geojson_map.hpp"
#include "pednav_indoor_map/geometry_2d.hpp"

namespace pednav::indoor_map {

namespace {

using nlohmann::json;

// Positions closer than this are the same point, m.
constexpr double kSamePointM = 1e-6;

std::string metres(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.2f", v);
    return s;
}

std::string feature_name(const std::string& kind, int index) { return kind + " feature " + std::to_string(index); }

int feature_of_pointer(const std::string& pointer) {
    const std::string prefix = "/features/";
    if (pointer.compare(0, prefix.size(), prefix) != 0) return -1;
    return std::atoi(pointer.c_str() + prefix.size());
}

// Whether every position lies on one line (a ring of no area; a crossed ring
// may have zero signed area and still be a shape).
bool collinear(const std::vector<Point2>& p) {
    size_t far = 0;
    double far_m = 0;
    for (size_t k = 1; k < p.size(); ++k) {
        const double d = std::hypot(p[k].e_m - p[0].e_m, p[k].n_m - p[0].n_m);
        if (d > far_m) far_m = d, far = k;
    }
    if (far_m < kSamePointM) return true;
    for (const Point2& q : p)
        if (std::fabs(orientation(p[0], p[far], q)) / far_m > kSamePointM) return false;
    return true;
}

bool same_point(const Point2& a, const Point2& b) { return std::hypot(a.e_m - b.e_m, a.n_m - b.n_m) < kSamePointM; }

class Checker {
public:
    Checker(const json& doc, const Map& map, const detail::PositionFrame& frame)
        : doc_(doc), map_(map), frame_(frame) {}

    std::vector<MapProblem> problems;

    void add(int feature, std::string pointer, std::string message) {
        problems.push_back({feature, std::move(pointer), std::move(message)});
    }

    // Rings and lines of every feature pednav reads.
    void geometry() {
        const json& features = doc_["features"];
        for (size_t i = 0; i < features.size(); ++i) {
            const std::string at = "/features/" + std::to_string(i);
            const detail::FeatureKind fk = detail::feature_kind(features[i], at);
            if (fk.kind.empty()) continue;
            const json& g = features[i]["geometry"];
            const std::string type = g["type"].get<std::string>();
            const std::string c = at + "/geometry/coordinates";
            const std::string name = feature_name(fk.kind, static_cast<int>(i));
            if (type == "LineString") line(static_cast<int>(i), name, frame_.points(g["coordinates"], c, 2, false), c);
            if (type == "Polygon")
                for (size_t r = 0; r < g["coordinates"].size(); ++r)
                    ring(static_cast<int>(i), name, static_cast<int>(r),
                         frame_.points(g["coordinates"][r], c + "/" + std::to_string(r), 3, true),
                         c + "/" + std::to_string(r));
        }
    }

    // Connectors reach floors something is on, arrows point the way they may be taken.
    void connectors() {
        std::vector<int> used;
        for (const auto& w : map_.walls) used.push_back(w.floor);
        for (const auto& z : map_.zones) used.push_back(z.floor);
        for (const auto& l : map_.landmarks) used.push_back(l.floor);
        auto is_used = [&](int f) { return std::find(used.begin(), used.end(), f) != used.end(); };
        for (const Connector& k : map_.connectors) {
            const std::string name = feature_name(kind_of(k), k.feature);
            const std::string props = "/features/" + std::to_string(k.feature) + "/properties";
            for (const auto& [key, floor] : {std::pair<const char*, int>{"pednav:floor", k.floor}, {"pednav:floor_to", k.floor_to}})
                if (!is_used(floor))
                    add(k.feature, props + "/" + key,
                        name + ": " + key + " " + std::to_string(floor) + " is a floor with no wall, zone or landmark");
            const bool climbs = k.floor_to > k.floor;
            if (k.is_arrow && ((k.direction == ConnectorDirection::up && !climbs) ||
                               (k.direction == ConnectorDirection::down && climbs)))
                add(k.feature, props + "/pednav:direction",
                    name + ": pednav:direction " + (climbs ? "down" : "up") + ", but its arrow goes " +
                        (climbs ? "up" : "down") + " from floor " + std::to_string(k.floor) + " to floor " +
                        std::to_string(k.floor_to));
        }
    }

    void start(const MapStart& s, double clearance_m) {
        const std::string where = "the start (" + metres(s.p.e_m) + ", " + metres(s.p.n_m) + ")";
        const std::string on = where + " on floor " + std::to_string(s.floor);
        if (!map_.floors.empty() && std::find(map_.floors.begin(), map_.floors.end(), s.floor) == map_.floors.end()) {
            add(-1, "", where + " is on floor " + std::to_string(s.floor) + ", where the map has nothing");
            return;
        }
        const WallSegment* nearest_wall = nullptr;
        double wall_m = std::numeric_limits<double>::infinity();
        for (const auto& w : map_.walls) {
            if (w.floor != s.floor) continue;
            const double d = distance_to_segment(s.p, w.a, w.b);
            if (d < wall_m) wall_m = d, nearest_wall = &w;
        }
        if (nearest_wall && wall_m < clearance_m)
            add(nearest_wall->feature, geometry_pointer(nearest_wall->feature),
                on + " is " + metres(wall_m) + " m from wall feature " + std::to_string(nearest_wall->feature) +
                    ", within its clearance of " + metres(clearance_m) + " m");
        const Zone* nearest_zone = nullptr;
        double zone_m = std::numeric_limits<double>::infinity();
        bool in_zone = false;
        for (const auto& z : map_.zones) {
            if (z.floor != s.floor) continue;
            const bool inside = point_in_polygon(s.p, z.rings);
            if (z.kind == ZoneKind::no_particles && inside)
                add(z.feature, geometry_pointer(z.feature), on + " is inside no_particles feature " + std::to_string(z.feature));
            if (z.kind != ZoneKind::walkable) continue;
            in_zone = in_zone || inside;
            const double d = distance_to_polyline(s.p, z.rings[0]);
            if (d < zone_m) zone_m = d, nearest_zone = &z;
        }
        if (nearest_zone && !in_zone)
            add(nearest_zone->feature, geometry_pointer(nearest_zone->feature),
                on + " is outside every zone of its floor; the nearest, zone feature " +
                    std::to_string(nearest_zone->feature) + ", is " + metres(zone_m) + " m away");
        if (!nearest_zone && nearest_wall) outside_walls(s, on);
    }

private:
    static std::string geometry_pointer(int feature) { return "/features/" + std::to_string(feature) + "/geometry"; }

    static std::string kind_of(const Connector& k) {
        return k.kind == ConnectorKind::stairs ? "stairs" : k.kind == ConnectorKind::escalator ? "escalator" : "lift";
    }

    void line(int feature, const std::string& name, const std::vector<Point2>& p, const std::string& at) {
        bool any_length = false;
        for (size_t k = 0; k + 1 < p.size(); ++k) any_length = any_length || !same_point(p[k], p[k + 1]);
        if (!any_length) {
            add(feature, at, name + ": its positions coincide (no length)");
            return;
        }
        for (size_t k = 0; k + 1 < p.size(); ++k)
            if (same_point(p[k], p[k + 1]))
                add(feature, at + "/" + std::to_string(k + 1),
                    name + ": positions " + std::to_string(k) + " and " + std::to_string(k + 1) + " coincide");
    }

    void ring(int feature, const std::string& name, int r, const std::vector<Point2>& p, const std::string& at) {
        const std::string which = name + ": ring " + std::to_string(r);
        for (size_t k = 0; k < p.size(); ++k)
            if (same_point(p[k], p[(k + 1) % p.size()])) {
                add(feature, at + "/" + std::to_string((k + 1) % p.size()),
                    which + ": positions " + std::to_string(k) + " and " + std::to_string((k + 1) % p.size()) +
                        " coincide");
                return;
            }
        if (collinear(p)) {
            add(feature, at, which + " has no area (its positions are on one line)");
            return;
        }
        int a = -1, b = -1;
        if (ring_self_intersects(p, &a, &b))
            add(feature, at + "/" + std::to_string(a),
                which + " crosses itself: edges " + std::to_string(a) + " and " + std::to_string(b) + " meet");
    }

    void outside_walls(const MapStart& s, const std::string& on) {
        double e0 = INFINITY, e1 = -INFINITY, n0 = INFINITY, n1 = -INFINITY;
        for (const auto& w : map_.walls) {
            if (w.floor != s.floor) continue;
            for (const Point2& q : {w.a, w.b}) e0 = std::min(e0, q.e_m), e1 = std::max(e1, q.e_m), n0 = std::min(n0, q.n_m), n1 = std::max(n1, q.n_m);
        }
        if (s.p.e_m < e0 || s.p.e_m > e1 || s.p.n_m < n0 || s.p.n_m > n1)
            add(-1, "", on + " is outside the walls of its floor (east " + metres(e0) + " to " + metres(e1) +
                            " m, north " + metres(n0) + " to " + metres(n1) + " m)");
    }

    const json& doc_;
    const Map& map_;
    const detail::PositionFrame& frame_;
};

}  // namespace

std::vector<MapProblem> check_map(std::string_view document, const std::optional<geodesy::GeodeticPoint>& origin,
                                  const MapCheckOptions& options) {
    Map map;
    try {
        map = read_geojson_map(document, origin);
    } catch (const MapError& e) {
        return {{feature_of_pointer(e.pointer), e.pointer, e.what()}};
    }
    const json doc = detail::parse_map_document(document);
    const detail::PositionFrame frame(doc, origin);
    Checker c(doc, map, frame);
    c.geometry();
    c.connectors();
    if (options.start) c.start(*options.start, options.wall_clearance_m);
    return c.problems;
}

}  // namespace pednav::indoor_map
