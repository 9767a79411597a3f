// SPDX-License-Identifier: Apache-2.0
// pednav.map/1 features -> Map: walls, zones, connectors and landmarks per
// floor (docs/maps.md, "Format pednav.map/1").
#include "pednav_indoor_map/geojson_map.hpp"

#include <algorithm>
#include <cmath>

#include "geojson_document.hpp"

namespace pednav::indoor_map {

namespace {

using nlohmann::json;
using detail::PositionFrame;

// Default reach of an arrow: how far from its line a walker counts as on the
// stairs, escalator or lift it draws, m.
constexpr double kArrowReachM = 1.0;

struct FeatureContext {
    const json& feature;
    const json& properties;
    std::string at;  // "/features/<i>"
    int index;
    int floor;
    std::string kind;
};

// The feature's geometry of one of `types`; returns its type.
std::string geometry_of(const FeatureContext& f, std::initializer_list<const char*> types, const json** coordinates) {
    const json* g = detail::member(f.feature, "geometry");
    std::string allowed;
    for (const char* t : types) allowed += std::string(allowed.empty() ? "" : " or ") + t;
    if (!g || !g->is_object())
        throw MapError(f.at + "/geometry", "a " + f.kind + " needs a geometry (" + allowed + ")");
    const std::string type = detail::string_member(*g, f.at + "/geometry", "type");
    if (std::find_if(types.begin(), types.end(), [&](const char* t) { return type == t; }) == types.end())
        throw MapError(f.at + "/geometry/type", "a " + f.kind + " is a " + allowed + ", not a " + type);
    *coordinates = detail::member(*g, "coordinates");
    if (!*coordinates) throw MapError(f.at + "/geometry/coordinates", "the geometry has no coordinates");
    return type;
}

std::vector<std::vector<Point2>> polygon_rings(const PositionFrame& frame, const json& coords, const std::string& at) {
    if (!coords.is_array() || coords.empty()) throw MapError(at, "a Polygon needs at least one ring");
    std::vector<std::vector<Point2>> rings;
    for (size_t r = 0; r < coords.size(); ++r) rings.push_back(frame.points(coords[r], at + "/" + std::to_string(r), 3, true));
    return rings;
}

void read_wall(const PositionFrame& frame, const FeatureContext& f, Map& m) {
    const json* c = nullptr;
    const std::string type = geometry_of(f, {"LineString", "Polygon"}, &c);
    const std::string at = f.at + "/geometry/coordinates";
    auto add = [&](const std::vector<Point2>& p, bool closed) {
        for (size_t k = 0; k + 1 < p.size(); ++k) m.walls.push_back({p[k], p[k + 1], f.floor, f.index});
        if (closed) m.walls.push_back({p.back(), p.front(), f.floor, f.index});
    };
    if (type == "LineString") add(frame.points(*c, at, 2, false), false);
    else
        for (const auto& ring : polygon_rings(frame, *c, at)) add(ring, true);
}

void read_zone(const PositionFrame& frame, const FeatureContext& f, ZoneKind kind, Map& m) {
    const json* c = nullptr;
    geometry_of(f, {"Polygon"}, &c);
    Zone z{kind, f.floor, polygon_rings(frame, *c, f.at + "/geometry/coordinates"), std::nan(""), f.index};
    if (kind == ZoneKind::altitude) {
        // pednav:height_m is a height like the positions' own (above the
        // ellipsoid in WGS-84, up in local metres): its up in the engine frame.
        const double h = detail::number_member(f.properties, f.at + "/properties", "pednav:height_m", -1e5, 1e5);
        double enu[3];
        frame.enu((*c)[0][0], f.at + "/geometry/coordinates/0/0", enu, &h);
        z.height_m = enu[2];
    }
    m.zones.push_back(std::move(z));
}

ConnectorDirection direction_of(const FeatureContext& f) {
    if (!detail::member(f.properties, "pednav:direction")) return ConnectorDirection::both;
    const std::string d = detail::string_member(f.properties, f.at + "/properties", "pednav:direction");
    if (d == "up") return ConnectorDirection::up;
    if (d == "down") return ConnectorDirection::down;
    if (d == "both") return ConnectorDirection::both;
    throw MapError(f.at + "/properties/pednav:direction", "unknown pednav:direction \"" + d + "\" (up, down or both)");
}

void read_connector(const PositionFrame& frame, const FeatureContext& f, ConnectorKind kind, Map& m) {
    const json* c = nullptr;
    const std::string type = geometry_of(f, {"LineString", "Polygon"}, &c);
    const std::string props = f.at + "/properties";
    Connector k;
    k.kind = kind;
    k.direction = direction_of(f);
    k.floor = f.floor;
    k.floor_to = detail::integer_member(f.properties, props, "pednav:floor_to");
    if (k.floor_to == k.floor)
        throw MapError(props + "/pednav:floor_to", "pednav:floor_to is pednav:floor (" + std::to_string(k.floor) +
                                                        "): a " + f.kind + " connects two floors");
    k.is_arrow = type == "LineString";
    k.area = k.is_arrow ? frame.points(*c, f.at + "/geometry/coordinates", 2, false)
                        : polygon_rings(frame, *c, f.at + "/geometry/coordinates")[0];
    k.reach_m = detail::member(f.properties, "pednav:reach_m")
                    ? detail::number_member(f.properties, props, "pednav:reach_m", 0.0, 100.0)
                    : k.is_arrow ? kArrowReachM : 0.0;
    k.feature = f.index;
    m.connectors.push_back(std::move(k));
}

void read_landmark(const PositionFrame& frame, const FeatureContext& f, Map& m) {
    const json* c = nullptr;
    geometry_of(f, {"Point"}, &c);
    m.landmarks.push_back({frame.point(*c, f.at + "/geometry/coordinates"), f.floor, f.index});
}

}  // namespace

std::optional<geodesy::GeodeticPoint> geojson_map_origin(std::string_view document) {
    return detail::origin_member(detail::parse_map_document(document));
}

Map read_geojson_map(std::string_view document, const std::optional<geodesy::GeodeticPoint>& origin) {
    const json doc = detail::parse_map_document(document);
    const PositionFrame frame(doc, origin);
    Map m;
    if (doc.contains("pednav:floor_height_m"))
        m.floor_height_m = detail::number_member(doc, "", "pednav:floor_height_m", 0.5, 100.0);
    const json& features = doc["features"];
    for (size_t i = 0; i < features.size(); ++i) {
        const json& feature = features[i];
        const std::string at = "/features/" + std::to_string(i);
        const detail::FeatureKind fk = detail::feature_kind(feature, at);
        if (fk.kind.empty()) continue;
        const std::string& kind = fk.kind;
        const json& props = *fk.properties;
        const FeatureContext f{feature, props, at, static_cast<int>(i),
                               detail::integer_member(props, at + "/properties", fk.floor_key), kind};
        if (kind == "wall") read_wall(frame, f, m);
        else if (kind == "zone") read_zone(frame, f, ZoneKind::walkable, m);
        else if (kind == "no_particles") read_zone(frame, f, ZoneKind::no_particles, m);
        else if (kind == "altitude_zone") read_zone(frame, f, ZoneKind::altitude, m);
        else if (kind == "stairs") read_connector(frame, f, ConnectorKind::stairs, m);
        else if (kind == "escalator") read_connector(frame, f, ConnectorKind::escalator, m);
        else if (kind == "lift") read_connector(frame, f, ConnectorKind::lift, m);
        else read_landmark(frame, f, m);
        m.floors.push_back(f.floor);
        if (!m.connectors.empty() && m.connectors.back().feature == f.index) m.floors.push_back(m.connectors.back().floor_to);
    }
    std::sort(m.floors.begin(), m.floors.end());
    m.floors.erase(std::unique(m.floors.begin(), m.floors.end()), m.floors.end());
    return m;
}

}  // namespace pednav::indoor_map
