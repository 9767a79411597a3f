// SPDX-License-Identifier: Apache-2.0
#include "geojson_document.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "pednav_strict_json/strict_json.hpp"

namespace pednav::indoor_map {

MapError::MapError(std::string pointer_, const std::string& message)
    : std::runtime_error(message), pointer(std::move(pointer_)) {}

namespace detail {

namespace {

std::string describe(const nlohmann::json& v) {
    std::string s = v.dump();
    if (s.size() > 40) s = s.substr(0, 37) + "...";
    return s;
}

bool finite_number(const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }

geodesy::GeodeticPoint origin_from_array(const nlohmann::json& o) {
    const std::string at = "/pednav:origin";
    if (o.size() < 2 || o.size() > 3)
        throw MapError(at, "pednav:origin is [longitude, latitude] or [longitude, latitude, height], got " + describe(o));
    for (size_t k = 0; k < o.size(); ++k)
        if (!finite_number(o[k])) throw MapError(at + "/" + std::to_string(k), "not a number: " + describe(o[k]));
    const double lon = o[0].get<double>(), lat = o[1].get<double>();
    if (std::fabs(lon) > 180) throw MapError(at + "/0", "longitude " + describe(o[0]) + " is beyond 180 degrees");
    if (std::fabs(lat) > 90) throw MapError(at + "/1", "latitude " + describe(o[1]) + " is beyond 90 degrees");
    return {lat, lon, o.size() > 2 ? o[2].get<double>() : 0.0};
}

geodesy::GeodeticPoint origin_from_object(const nlohmann::json& o) {
    const std::string at = "/pednav:origin";
    for (auto it = o.begin(); it != o.end(); ++it)
        if (it.key() != "lat_deg" && it.key() != "lon_deg" && it.key() != "height_m")
            throw MapError(at + "/" + pointer_token(it.key()), "unknown member \"" + it.key() +
                                                                   "\" (pednav:origin is [longitude, latitude, height])");
    geodesy::GeodeticPoint p;
    p.lat_deg = number_member(o, at, "lat_deg", -90.0, 90.0);
    p.lon_deg = number_member(o, at, "lon_deg", -180.0, 180.0);
    p.height_m = o.contains("height_m") ? number_member(o, at, "height_m", -1e5, 1e5) : 0.0;
    return p;
}

}  // namespace

FeatureKind feature_kind(const nlohmann::json& feature, const std::string& at) {
    static const nlohmann::json no_properties = nlohmann::json::object();
    if (!feature.is_object()) throw MapError(at, "a feature is a JSON object");
    const nlohmann::json* p = member(feature, "properties");
    const nlohmann::json* props = p && p->is_object() ? p : &no_properties;
    if (member(*props, "pednav:kind")) {
        const std::string kind = string_member(*props, at + "/properties", "pednav:kind");
        static const char* const kKinds[] = {"wall",   "zone",      "no_particles", "altitude_zone",
                                             "stairs", "escalator", "lift",         "landmark"};
        if (std::find(std::begin(kKinds), std::end(kKinds), kind) == std::end(kKinds))
            throw MapError(at + "/properties/pednav:kind",
                           "unknown pednav:kind \"" + kind +
                               "\" (wall, zone, no_particles, altitude_zone, stairs, escalator, lift or landmark)");
        return {kind, "pednav:floor", props};
    }
    // The simulator's maps before pednav.map/1 named their walls with plain
    // "kind": "wall" and "floor".
    if (const nlohmann::json* legacy = member(*props, "kind"); legacy && *legacy == "wall") return {"wall", "floor", props};
    return {"", nullptr, props};
}

std::string pointer_token(const std::string& key) {
    std::string s;
    for (char c : key) {
        if (c == '~') s += "~0";
        else if (c == '/') s += "~1";
        else s += c;
    }
    return s;
}

nlohmann::json parse_map_document(std::string_view document) {
    nlohmann::json doc;
    try {
        doc = strict_json::parse(document);
    } catch (const strict_json::Error& e) {  // not JSON, too deep, a key twice, 1e400, a NUL
        throw MapError(e.pointer, e.what());
    }
    if (!doc.is_object()) throw MapError("", "the map is not a GeoJSON FeatureCollection (not a JSON object)");
    const auto type = doc.find("type");
    if (type == doc.end() || *type != "FeatureCollection")
        throw MapError("/type", "the map is not a GeoJSON FeatureCollection (\"type\": \"FeatureCollection\")");
    const auto features = doc.find("features");
    if (features == doc.end() || !features->is_array())
        throw MapError("/features", "a FeatureCollection needs a \"features\" array");
    return doc;
}

std::optional<geodesy::GeodeticPoint> origin_member(const nlohmann::json& doc) {
    const auto o = doc.find("pednav:origin");
    if (o == doc.end()) return std::nullopt;
    if (o->is_array()) return origin_from_array(*o);
    if (o->is_object()) return origin_from_object(*o);
    throw MapError("/pednav:origin", "pednav:origin is [longitude, latitude, height], got " + describe(*o));
}

const nlohmann::json* member(const nlohmann::json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

double number_member(const nlohmann::json& object, const std::string& at, const char* key, double min, double max) {
    const nlohmann::json* v = member(object, key);
    const std::string where = at + "/" + pointer_token(key);
    if (!v) throw MapError(where, std::string(key) + " is missing");
    if (!finite_number(*v)) throw MapError(where, std::string(key) + " is not a number: " + describe(*v));
    const double x = v->get<double>();
    if (x < min || x > max)
        throw MapError(where, std::string(key) + " = " + describe(*v) + " is outside [" + describe(min) + ", " +
                                  describe(max) + "]");
    return x;
}

int integer_member(const nlohmann::json& object, const std::string& at, const char* key) {
    const double x = number_member(object, at, key, -1000.0, 1000.0);
    if (x != std::floor(x))
        throw MapError(at + "/" + pointer_token(key), std::string(key) + " is not an integer: " + describe(x));
    return static_cast<int>(x);
}

std::string string_member(const nlohmann::json& object, const std::string& at, const char* key) {
    const nlohmann::json* v = member(object, key);
    const std::string where = at + "/" + pointer_token(key);
    if (!v) throw MapError(where, std::string(key) + " is missing");
    if (!v->is_string()) throw MapError(where, std::string(key) + " is not a string: " + describe(*v));
    return v->get<std::string>();
}

PositionFrame::PositionFrame(const nlohmann::json& doc, const std::optional<geodesy::GeodeticPoint>& engine_origin) {
    const std::optional<geodesy::GeodeticPoint> own = origin_member(doc);
    if (doc.contains("pednav:crs")) {
        const std::string crs = string_member(doc, "", "pednav:crs");
        if (crs == "local-enu") local_ = true;
        else if (crs != "wgs84")
            throw MapError("/pednav:crs", "unknown pednav:crs \"" + crs + "\" (wgs84 or local-enu)");
    }
    if (local_) {
        // Local metres are the engine's frame unless both origins are known
        // and differ: then they are moved from the document's to the engine's.
        if (own && engine_origin &&
            (own->lat_deg != engine_origin->lat_deg || own->lon_deg != engine_origin->lon_deg ||
             own->height_m != engine_origin->height_m)) {
            shift_ = true;
            document_origin_ = *own;
            origin_ = *engine_origin;
        }
        return;
    }
    if (engine_origin) origin_ = *engine_origin;
    else if (own) origin_ = *own;
    else
        throw MapError("", "the map is in WGS-84 degrees and neither the engine nor the map (pednav:origin) has an "
                           "origin; set one or give the map \"pednav:crs\": \"local-enu\"");
}

void PositionFrame::enu(const nlohmann::json& position, const std::string& at, double enu_m[3],
                        const double* height_m) const {
    if (!position.is_array() || position.size() < 2 || position.size() > 3)
        throw MapError(at, std::string("a position is ") +
                               (local_ ? "[east_m, north_m] or [east_m, north_m, up_m]"
                                       : "[longitude, latitude] or [longitude, latitude, height]") +
                               ", got " + describe(position));
    for (size_t k = 0; k < position.size(); ++k)
        if (!finite_number(position[k]))
            throw MapError(at + "/" + std::to_string(k), "not a number: " + describe(position[k]));
    const double x = position[0].get<double>(), y = position[1].get<double>();
    const double z = height_m ? *height_m : position.size() > 2 ? position[2].get<double>() : local_ ? 0.0 : origin_.height_m;
    if (local_) {
        if (!shift_) {
            enu_m[0] = x, enu_m[1] = y, enu_m[2] = z;
            return;
        }
        const double own[3] = {x, y, z};
        double lat = 0, lon = 0, h = 0;
        geodesy::enu_to_geodetic(document_origin_, own, &lat, &lon, &h);
        geodesy::geodetic_to_enu(origin_, lat, lon, h, enu_m);
        return;
    }
    if (std::fabs(x) > 180) throw MapError(at + "/0", "longitude " + describe(position[0]) + " is beyond 180 degrees");
    if (std::fabs(y) > 90) throw MapError(at + "/1", "latitude " + describe(position[1]) + " is beyond 90 degrees");
    geodesy::geodetic_to_enu(origin_, y, x, z, enu_m);
}

Point2 PositionFrame::point(const nlohmann::json& position, const std::string& at) const {
    double e[3];
    enu(position, at, e);
    return {e[0], e[1]};
}

std::vector<Point2> PositionFrame::points(const nlohmann::json& positions, const std::string& at, size_t min_count,
                                          bool ring) const {
    if (!positions.is_array()) throw MapError(at, "not an array of positions: " + describe(positions));
    size_t n = positions.size();
    if (ring && n > 1 && positions[n - 1] == positions[0]) --n;
    if (n < min_count)
        throw MapError(at, (ring ? "a ring needs at least " : "a LineString needs at least ") +
                               std::to_string(min_count) + " positions" + (ring ? " besides the closing one" : "") +
                               ", got " + std::to_string(n));
    std::vector<Point2> out;
    out.reserve(n);
    for (size_t k = 0; k < n; ++k) out.push_back(point(positions[k], at + "/" + std::to_string(k)));
    return out;
}

}  // namespace detail
}  // namespace pednav::indoor_map
