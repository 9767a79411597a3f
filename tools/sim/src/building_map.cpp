// SPDX-License-Identifier: Apache-2.0
#include <pednav_sim/building_map.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <pednav_geodesy/enu.hpp>

namespace pednav::sim {

namespace {

using P2 = std::array<double, 2>;

nlohmann::json lonlat(const geodesy::GeodeticPoint& o, const P2& p) {
    const double enu[3] = {p[0], p[1], 0.0};
    double lat = 0.0, lon = 0.0, h = 0.0;
    geodesy::enu_to_geodetic(o, enu, &lat, &lon, &h);
    return {lon, lat};
}

int floor_of(const Route& r, double z_m) { return static_cast<int>(std::lround(z_m / r.floor_height_m)); }

bool on_a_floor(const Route& r, double z_m) {
    const double f = z_m / r.floor_height_m;
    return std::fabs(f - std::round(f)) < 1e-6;
}

// Where segment [a, b] crosses [p, q] properly (each has its ends strictly on
// both sides of the other; touching is no crossing), as the parameter along
// [p, q] (0 at p, 1 at q); a negative value when they do not cross.
double crossing_on(const P2& a, const P2& b, const P2& p, const P2& q) {
    const double rx = b[0] - a[0], ry = b[1] - a[1], sx = q[0] - p[0], sy = q[1] - p[1];
    const double den = rx * sy - ry * sx;
    if (std::fabs(den) < 1e-12) return -1.0;
    const double t = ((p[0] - a[0]) * sy - (p[1] - a[1]) * sx) / den;  // along [a, b]
    const double u = ((p[0] - a[0]) * ry - (p[1] - a[1]) * rx) / den;  // along [p, q]
    return t > 0.0 && t < 1.0 && u > 0.0 && u < 1.0 ? u : -1.0;
}

// The route's horizontal path segments on `floor` (level ones and the level
// ends of stairs).
std::vector<std::pair<P2, P2>> path_on_floor(const Route& r, int floor) {
    std::vector<std::pair<P2, P2>> out;
    for (size_t i = 1; i < r.waypoints.size(); ++i) {
        const double* a = r.waypoints[i - 1].enu_m;
        const double* b = r.waypoints[i].enu_m;
        if (floor_of(r, a[2]) == floor || floor_of(r, b[2]) == floor) out.push_back({{a[0], a[1]}, {b[0], b[1]}});
    }
    return out;
}

// The pieces of one wall polyline left after cutting a doorway wherever the
// path on its floor crosses it.
std::vector<std::vector<P2>> wall_pieces(const Wall& w, const std::vector<std::pair<P2, P2>>& path) {
    std::vector<std::vector<P2>> pieces(1);
    const auto& pts = w.points_enu_m;
    if (!pts.empty()) pieces.back().push_back(pts[0]);
    for (size_t k = 0; k + 1 < pts.size(); ++k) {
        const P2 &p = pts[k], &q = pts[k + 1];
        const double len = std::hypot(q[0] - p[0], q[1] - p[1]);
        std::vector<std::pair<double, double>> cuts;  // parameter intervals along [p, q]
        for (const auto& [a, b] : path) {
            const double u = crossing_on(a, b, p, q);
            if (u >= 0.0 && len > 0.0) {
                const double half = 0.5 * kDoorWidthM / len;
                cuts.push_back({std::max(0.0, u - half), std::min(1.0, u + half)});
            }
        }
        std::sort(cuts.begin(), cuts.end());
        auto at = [&](double u) { return P2{p[0] + u * (q[0] - p[0]), p[1] + u * (q[1] - p[1])}; };
        double done = 0.0;
        for (const auto& [u0, u1] : cuts) {
            if (u1 <= done) continue;
            if (u0 > done) pieces.back().push_back(at(u0));
            pieces.emplace_back();
            done = std::max(done, u1);
            if (done < 1.0) pieces.back().push_back(at(done));
        }
        if (done < 1.0) pieces.back().push_back(q);
    }
    pieces.erase(std::remove_if(pieces.begin(), pieces.end(), [](const auto& s) { return s.size() < 2; }),
                 pieces.end());
    return pieces;
}

struct Flight {
    int floor, floor_to;
    std::vector<P2> points;  // from the foot on `floor` to the head on `floor_to`
};

bool same_flight(const Flight& a, const Flight& b) {
    auto same_points = [](const std::vector<P2>& x, const std::vector<P2>& y) {
        if (x.size() != y.size()) return false;
        for (size_t k = 0; k < x.size(); ++k)
            if (std::hypot(x[k][0] - y[k][0], x[k][1] - y[k][1]) > 1e-6) return false;
        return true;
    };
    if (a.floor == b.floor && a.floor_to == b.floor_to) return same_points(a.points, b.points);
    if (a.floor == b.floor_to && a.floor_to == b.floor) {
        std::vector<P2> reversed(b.points.rbegin(), b.points.rend());
        return same_points(a.points, reversed);
    }
    return false;
}

// Each climb between two waypoints on whole floors, by stairs, once (walked
// down again it is the same stairs).
std::vector<Flight> flights(const Route& r) {
    std::vector<Flight> out;
    size_t from = 0;
    for (size_t i = 1; i < r.waypoints.size(); ++i) {
        const double z = r.waypoints[i].enu_m[2];
        if (!on_a_floor(r, z)) continue;
        const int f0 = floor_of(r, r.waypoints[from].enu_m[2]), f1 = floor_of(r, z);
        if (f0 != f1) {
            Flight f{f0, f1, {}};
            for (size_t k = from; k <= i; ++k) f.points.push_back({r.waypoints[k].enu_m[0], r.waypoints[k].enu_m[1]});
            if (std::none_of(out.begin(), out.end(), [&](const Flight& g) { return same_flight(f, g); }))
                out.push_back(std::move(f));
        }
        from = i;
    }
    return out;
}

// A place of known height: a level stretch of the route on a whole floor, at
// least this long, m, and this wide around its line, m.
constexpr double kAltitudeZoneMinLengthM = 2.0;
constexpr double kAltitudeZoneWidthM = 2.0;

struct LevelStretch {
    int floor;
    P2 a, b;
};

// Each level segment of the route on a whole floor, once (walked back, it is the same place).
std::vector<LevelStretch> level_stretches(const Route& r) {
    std::vector<LevelStretch> out;
    for (size_t i = 1; i < r.waypoints.size(); ++i) {
        const double *a = r.waypoints[i - 1].enu_m, *b = r.waypoints[i].enu_m;
        if (!on_a_floor(r, a[2]) || floor_of(r, a[2]) != floor_of(r, b[2]) || std::fabs(a[2] - b[2]) > 1e-6) continue;
        if (std::hypot(b[0] - a[0], b[1] - a[1]) < kAltitudeZoneMinLengthM) continue;
        const LevelStretch s{floor_of(r, a[2]), {a[0], a[1]}, {b[0], b[1]}};
        auto same = [](const P2& p, const P2& q) { return std::hypot(p[0] - q[0], p[1] - q[1]) < 1e-6; };
        if (std::none_of(out.begin(), out.end(), [&](const LevelStretch& t) {
                return t.floor == s.floor && ((same(t.a, s.a) && same(t.b, s.b)) || (same(t.a, s.b) && same(t.b, s.a)));
            }))
            out.push_back(s);
    }
    return out;
}

// The rectangle kAltitudeZoneWidthM wide around a stretch, counter-clockwise.
std::vector<P2> around(const LevelStretch& s) {
    const double len = std::hypot(s.b[0] - s.a[0], s.b[1] - s.a[1]);
    const double h = 0.5 * kAltitudeZoneWidthM, nx = -(s.b[1] - s.a[1]) / len * h, ny = (s.b[0] - s.a[0]) / len * h;
    return {{s.a[0] - nx, s.a[1] - ny}, {s.b[0] - nx, s.b[1] - ny}, {s.b[0] + nx, s.b[1] + ny}, {s.a[0] + nx, s.a[1] + ny}};
}

nlohmann::json feature(const nlohmann::json& geometry, const nlohmann::json& properties) {
    return {{"type", "Feature"}, {"geometry", geometry}, {"properties", properties}};
}

}  // namespace

nlohmann::json building_map(const Route& route) {
    const geodesy::GeodeticPoint o{route.origin_lat_deg, route.origin_lon_deg, route.origin_height_m};
    nlohmann::json fc = {{"type", "FeatureCollection"}, {"features", nlohmann::json::array()}};
    auto& features = fc["features"];
    for (const Wall& w : route.walls) {
        for (const auto& piece : wall_pieces(w, path_on_floor(route, w.floor))) {
            nlohmann::json coords = nlohmann::json::array();
            for (const auto& p : piece) coords.push_back(lonlat(o, p));
            features.push_back(feature({{"type", "LineString"}, {"coordinates", coords}},
                                       {{"pednav:kind", "wall"}, {"pednav:floor", w.floor}}));
        }
    }
    for (const Flight& f : flights(route)) {
        nlohmann::json coords = nlohmann::json::array();
        for (const auto& p : f.points) coords.push_back(lonlat(o, p));
        features.push_back(feature({{"type", "LineString"}, {"coordinates", coords}},
                                   {{"pednav:kind", "stairs"},
                                    {"pednav:floor", f.floor},
                                    {"pednav:floor_to", f.floor_to},
                                    {"pednav:direction", "both"}}));
    }
    // Altitude zones only where the route has floors above or below: a single-floor walk has no
    // barometer drift to hold.
    const bool several_floors = !flights(route).empty();
    for (const LevelStretch& st : several_floors ? level_stretches(route) : std::vector<LevelStretch>{}) {
        nlohmann::json ring = nlohmann::json::array();
        for (const auto& p : around(st)) ring.push_back(lonlat(o, p));
        ring.push_back(ring.front());
        features.push_back(feature({{"type", "Polygon"}, {"coordinates", {ring}}},
                                   {{"pednav:kind", "altitude_zone"},
                                    {"pednav:floor", st.floor},
                                    {"pednav:height_m", o.height_m + st.floor * route.floor_height_m}}));
    }
    const double* s = route.waypoints.front().enu_m;
    features.push_back(feature({{"type", "Point"}, {"coordinates", lonlat(o, {s[0], s[1]})}},
                               {{"pednav:kind", "landmark"}, {"pednav:floor", floor_of(route, s[2])}, {"name", "start"}}));
    nlohmann::json path = nlohmann::json::array();
    for (const Waypoint& w : route.waypoints) path.push_back(lonlat(o, {w.enu_m[0], w.enu_m[1]}));
    features.push_back(feature({{"type", "LineString"}, {"coordinates", path}}, {{"kind", "route"}, {"name", route.name}}));
    fc["pednav:origin"] = {o.lon_deg, o.lat_deg, o.height_m};
    fc["pednav:floor_height_m"] = route.floor_height_m;
    return fc;
}

}  // namespace pednav::sim
