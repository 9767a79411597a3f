// SPDX-License-Identifier: Apache-2.0
// The parts of a pednav.map/1 document every reader of it needs: the parsed
// JSON with its top-level members checked, typed members of a feature with
// errors naming them by JSON pointer, and the frame that turns the
// document's positions into metres east, north and up of the engine origin.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "pednav_indoor_map/geojson_map.hpp"

namespace pednav::indoor_map::detail {

// The document as JSON; throws MapError("", ...) when it is not JSON or not a
// FeatureCollection with a "features" array.
nlohmann::json parse_map_document(std::string_view document);

// "pednav:origin", [lon, lat] or [lon, lat, height] (the simulator's earlier
// {"lat_deg", "lon_deg", "height_m"} object is read too); nullopt when absent.
std::optional<geodesy::GeodeticPoint> origin_member(const nlohmann::json& doc);

// Members of `object` (at JSON pointer `at`), each error naming the member.
const nlohmann::json* member(const nlohmann::json& object, const char* key);
double number_member(const nlohmann::json& object, const std::string& at, const char* key, double min, double max);
int integer_member(const nlohmann::json& object, const std::string& at, const char* key);
std::string string_member(const nlohmann::json& object, const std::string& at, const char* key);

// What a feature is: its pednav:kind (checked against the known kinds), or
// for the simulator's earlier maps a plain "kind": "wall"; an empty kind for
// a feature pednav does not read (no pednav:kind: a GIS extra).
struct FeatureKind {
    std::string kind;
    const char* floor_key;           // "pednav:floor", or "floor" in the earlier form
    const nlohmann::json* properties;  // an empty object when the feature has none
};
FeatureKind feature_kind(const nlohmann::json& feature, const std::string& at);

// JSON pointer reference token of a member name ("~" and "/" escaped).
std::string pointer_token(const std::string& key);

// Positions of the document -> metres in the engine's local frame.
class PositionFrame {
public:
    // Throws MapError when the document is in WGS-84 and neither the engine
    // nor the document has an origin, or when its pednav:crs is unknown.
    PositionFrame(const nlohmann::json& doc, const std::optional<geodesy::GeodeticPoint>& engine_origin);

    bool local_metres() const { return local_; }
    // The position at `at`, east/north/up metres of the engine origin; when
    // `height_m` is given it replaces the position's own height (or up).
    void enu(const nlohmann::json& position, const std::string& at, double enu_m[3],
             const double* height_m = nullptr) const;
    Point2 point(const nlohmann::json& position, const std::string& at) const;
    // An array of positions (a LineString's coordinates, a ring), at least
    // `min_count`; a ring's closing position (equal to its first) is dropped.
    std::vector<Point2> points(const nlohmann::json& positions, const std::string& at, size_t min_count,
                               bool ring) const;

private:
    bool local_ = false;
    bool shift_ = false;  // local metres of the document's own origin, moved to the engine's
    geodesy::GeodeticPoint origin_{};
    geodesy::GeodeticPoint document_origin_{};
};

}  // namespace pednav::indoor_map::detail
