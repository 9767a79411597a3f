// SPDX-License-Identifier: Apache-2.0
#include "map_writer.hpp"

#include <cmath>

namespace pednav::indoor_map::detail {

MapWriter::MapWriter(const MapConversion& conversion, const SourcePoint& zero_source_m)
    : conversion_(conversion), zero_(zero_source_m) {
    doc_ = {{"type", "FeatureCollection"}};
    if (conversion_.origin) {
        const auto& o = *conversion_.origin;
        doc_["pednav:origin"] = {o.lon_deg, o.lat_deg, o.height_m};
    } else {
        doc_["pednav:crs"] = "local-enu";
    }
    doc_["features"] = nlohmann::json::array();
}

nlohmann::json MapWriter::position(const SourcePoint& p) const {
    const Point2 local = image_metres_to_local(p[0], p[1], zero_);
    if (!conversion_.origin) {
        // 0.1 mm: far below any map's drawing precision, and short to print.
        auto tenth_mm = [](double v) { return std::round(v * 1e4) / 1e4; };
        return {tenth_mm(local.e_m), tenth_mm(local.n_m)};
    }
    const double enu[3] = {local.e_m, local.n_m, 0.0};
    double lat = 0, lon = 0, h = 0;
    geodesy::enu_to_geodetic(*conversion_.origin, enu, &lat, &lon, &h);
    return {lon, lat};
}

void MapWriter::add(const std::string& kind, int floor, nlohmann::json geometry, nlohmann::json properties) {
    if (!properties.is_object()) properties = nlohmann::json::object();
    if (!kind.empty()) {
        properties["pednav:kind"] = kind;
        properties["pednav:floor"] = floor;
    }
    doc_["features"].push_back({{"type", "Feature"}, {"geometry", std::move(geometry)}, {"properties", std::move(properties)}});
}

void MapWriter::line(const std::string& kind, int floor, const std::vector<SourcePoint>& points,
                     nlohmann::json properties) {
    nlohmann::json c = nlohmann::json::array();
    for (const auto& p : points) c.push_back(position(p));
    add(kind, floor, {{"type", "LineString"}, {"coordinates", std::move(c)}}, std::move(properties));
}

void MapWriter::polygon(const std::string& kind, int floor, std::vector<SourcePoint> ring, nlohmann::json properties) {
    nlohmann::json c = nlohmann::json::array();
    for (const auto& p : ring) c.push_back(position(p));
    if (!ring.empty()) c.push_back(position(ring.front()));  // GeoJSON rings are closed
    add(kind, floor, {{"type", "Polygon"}, {"coordinates", nlohmann::json::array({std::move(c)})}},
        std::move(properties));
}

void MapWriter::point(const std::string& kind, int floor, const SourcePoint& p, nlohmann::json properties) {
    add(kind, floor, {{"type", "Point"}, {"coordinates", position(p)}}, std::move(properties));
}

}  // namespace pednav::indoor_map::detail
