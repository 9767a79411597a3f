// SPDX-License-Identifier: Apache-2.0
// HuMoLiRe's MapEditor JSON (map_data.json) -> pednav.map/1.
#include <cmath>
#include <stdexcept>

#include "map_writer.hpp"
#include "pednav_indoor_map/map_convert.hpp"
#include "pednav_strict_json/strict_json.hpp"

namespace pednav::indoor_map {

namespace {

using nlohmann::json;

struct Source {
    const SourceFile& file;

    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const {
        throw std::runtime_error(file.name + ":" + pointer + ": " + message);
    }
    const json& at(const json& object, const std::string& pointer, const char* key) const {
        if (!object.is_object() || !object.contains(key)) fail(pointer + "/" + key, std::string(key) + " is missing");
        return object[key];
    }
    double number(const json& object, const std::string& pointer, const char* key) const {
        const json& v = at(object, pointer, key);
        if (!v.is_number() || !std::isfinite(v.get<double>())) fail(pointer + "/" + key, "not a number: " + v.dump());
        return v.get<double>();
    }
    int integer(const json& object, const std::string& pointer, const char* key) const {
        const double v = number(object, pointer, key);
        if (v != std::floor(v) || std::fabs(v) > 1000) fail(pointer + "/" + key, "not a floor number: " + at(object, pointer, key).dump());
        return static_cast<int>(v);
    }
};

}  // namespace

std::string humolire_to_geojson(const SourceFile& map_data, const MapConversion& conversion) {
    const Source src{map_data};
    json doc;
    try {
        doc = strict_json::parse(map_data.text);
    } catch (const strict_json::Error& e) {  // not JSON, too deep, a key twice, a number beyond a double
        throw std::runtime_error(map_data.name + (e.pointer.empty() ? "" : ":" + e.pointer) + ": " + e.what());
    }
    if (!doc.is_object()) src.fail("", "not a MapEditor map (a JSON object with \"links\" and \"scale\")");
    double scale = src.number(doc, "", "scale");
    if (!(scale > 0)) src.fail("/scale", "the scale (m per pixel) must be positive");
    if (conversion.scale_m_per_px) {
        if (!(*conversion.scale_m_per_px > 0)) throw std::invalid_argument("the scale (m per pixel) must be positive");
        scale = *conversion.scale_m_per_px;
    }
    const int start_floor = doc.contains("start_floor") ? src.integer(doc, "", "start_floor") : 0;
    for (const char* unread : {"polygons", "arrows"})
        if (doc.contains(unread) && !(doc[unread].is_array() && doc[unread].empty()))
            src.fail(std::string("/") + unread, std::string("MapEditor ") + unread +
                                                    " are not read from this format (only links, as walls)");

    // HuMoLiRe's metres have y up from the image's bottom edge (the image is
    // y_range[1] pixels tall): (x, y) is (x, height - y) in image metres.
    const json& y_range = src.at(doc, "", "y_range");
    if (!y_range.is_array() || y_range.size() != 2 || !y_range[1].is_number() || !std::isfinite(y_range[1].get<double>()))
        src.fail("/y_range", "not a [first, last] pair of pixel rows: " + y_range.dump());
    const double image_height_m = y_range[1].get<double>() * scale;
    const detail::SourcePoint start = conversion.start_source_m.value_or(detail::SourcePoint{0.0, 0.0});
    const detail::SourcePoint start_image_m{start[0], image_height_m - start[1]};
    detail::MapWriter out(conversion, start_image_m);
    if (doc.contains("height")) out.top("pednav:floor_height_m", src.number(doc, "", "height"));
    const json& links = src.at(doc, "", "links");
    if (!links.is_array()) src.fail("/links", "not an array");
    for (size_t i = 0; i < links.size(); ++i) {
        const std::string at = "/links/" + std::to_string(i);
        const json& link = links[i];
        const int layer = link.contains("layer") ? src.integer(link, at, "layer")
                                                 : src.integer(src.at(link, at, "node0"), at + "/node0", "layer");
        std::vector<detail::SourcePoint> ends;
        for (const char* node : {"node0", "node1"}) {
            const json& n = src.at(link, at, node);
            const std::string np = at + "/" + node;
            ends.push_back({src.number(n, np, "x") * scale, src.number(n, np, "y") * scale});
        }
        json props = {{"source", "link " + (link.contains("id") ? link["id"].dump() : std::to_string(i))}};
        out.line("wall", layer - start_floor, ends, std::move(props));
    }
    if (conversion.start_source_m) out.point("landmark", 0, start_image_m, {{"name", "start"}});
    return out.dump();
}

}  // namespace pednav::indoor_map
