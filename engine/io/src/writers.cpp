// SPDX-License-Identifier: Apache-2.0
// GeoJSON and GPX.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>

#include "pednav_io/gnss_log.hpp"
#include "pednav_io/writers.hpp"
#include "writer_fields.hpp"

namespace pednav::io {

namespace {

using detail::class_name;
using detail::h_sigma_m;
using detail::has_floor;
using detail::heading_deg;
using detail::kRadToDeg;
using detail::OutFile;

// GeoJSON and GPX keep at most one position per this interval (plus the last).
constexpr int64_t kThinInterval_ns = 100000000;

nlohmann::json floor_of(const pn_position_t& p) { return has_floor(p) ? nlohmann::json(p.floor) : nlohmann::json(); }

nlohmann::json point_feature(const nlohmann::json& coordinates, nlohmann::json properties) {
    return {{"type", "Feature"},
            {"geometry", {{"type", "Point"}, {"coordinates", coordinates}}},
            {"properties", std::move(properties)}};
}

std::vector<size_t> thinned(const std::vector<pn_position_t>& positions) {
    std::vector<size_t> keep;
    for (size_t i = 0; i < positions.size(); ++i) {
        const bool floor_changed =
            i > 0 && has_floor(positions[i]) && positions[i].floor != positions[i - 1].floor;
        if (keep.empty() || i + 1 == positions.size() || floor_changed ||
            positions[i].header.t_ns - positions[keep.back()].header.t_ns >= kThinInterval_ns) {
            keep.push_back(i);
        }
    }
    return keep;
}

// The last position at or before t_ns (the first one when none is).
size_t position_at(const std::vector<pn_position_t>& positions, int64_t t_ns) {
    size_t lo = 0, hi = positions.size();
    while (lo < hi) {
        const size_t mid = (lo + hi) / 2;
        if (positions[mid].header.t_ns <= t_ns)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo == 0 ? 0 : lo - 1;
}

nlohmann::json coordinates(const double enu[3], const Origin& origin) {
    if (!origin.known) return {enu[0], enu[1], enu[2]};
    double lat = 0, lon = 0, h = 0;
    geodesy::enu_to_geodetic(origin, enu, &lat, &lon, &h);
    return {lon, lat, h};
}

}  // namespace

void write_geojson(const std::string& path, const std::vector<pn_position_t>& positions,
                   const std::vector<pn_stride_t>& strides, const Origin& origin, const GeoJsonExtras& extras) {
    using nlohmann::json;
    json features = json::array();
    json line = json::array();
    json times = json::array(), sources = json::array(), floors = json::array();
    json position_points = json::array();
    for (size_t i : thinned(positions)) {
        const pn_position_t& p = positions[i];
        line.push_back(coordinates(p.pos_enu_m, origin));
        times.push_back(static_cast<double>(p.header.t_ns) * 1e-9);
        sources.push_back(position_source_name(p.source));
        floors.push_back(floor_of(p));
        if (extras.position_points) {
            position_points.push_back(point_feature(line.back(), {{"kind", "position"},
                                                                  {"t_s", times.back()},
                                                                  {"source", sources.back()},
                                                                  {"floor", floors.back()},
                                                                  {"heading_deg", heading_deg(p.heading_rad)},
                                                                  {"h_sigma_m", h_sigma_m(p)}}));
        }
    }
    if (!positions.empty()) {
        features.push_back({{"type", "Feature"},
                            {"geometry", {{"type", "LineString"}, {"coordinates", line}}},
                            {"properties",
                             {{"kind", "track"},
                              {"times_s", times},
                              {"sources", sources},
                              {"floors", floors},
                              {"t_start_s", times.front()},
                              {"t_end_s", times.back()}}}});
    }
    for (const auto& s : strides) {
        if (positions.empty()) break;
        const pn_position_t& p = positions[position_at(positions, s.header.t_ns)];
        features.push_back(
            {{"type", "Feature"},
             {"geometry", {{"type", "Point"}, {"coordinates", coordinates(p.pos_enu_m, origin)}}},
             {"properties",
              {{"kind", "step"},
               {"index", s.index},
               {"t_s", static_cast<double>(s.header.t_ns) * 1e-9},
               {"t_start_s", static_cast<double>(s.t_start_ns) * 1e-9},
               {"length_m", s.length_m},
               {"heading_change_deg", s.heading_change_rad * kRadToDeg},
               {"class", class_name(s.stride_class)}}}});
    }
    bool have_floor = false;
    int32_t last_floor = 0;
    for (const auto& p : positions) {
        if (!has_floor(p)) continue;
        if (have_floor && p.floor != last_floor) {
            features.push_back(
                {{"type", "Feature"},
                 {"geometry", {{"type", "Point"}, {"coordinates", coordinates(p.pos_enu_m, origin)}}},
                 {"properties",
                  {{"kind", "floor_change"},
                   {"t_s", static_cast<double>(p.header.t_ns) * 1e-9},
                   {"from_floor", last_floor},
                   {"to_floor", p.floor}}}});
        }
        have_floor = true;
        last_floor = p.floor;
    }
    for (size_t i = 1; i < positions.size(); ++i) {
        const pn_position_t& p = positions[i];
        if (p.source == positions[i - 1].source) continue;
        features.push_back(point_feature(coordinates(p.pos_enu_m, origin),
                                         {{"kind", "source_change"},
                                          {"t_s", static_cast<double>(p.header.t_ns) * 1e-9},
                                          {"from_source", position_source_name(positions[i - 1].source)},
                                          {"to_source", position_source_name(p.source)}}));
    }
    for (auto& f : position_points) features.push_back(std::move(f));
    if (extras.gnss_fixes != nullptr) {
        for (const pn_gnss_t& g : *extras.gnss_fixes) {
            // A fix is WGS-84 already; without an origin it goes to the local frame of none: left out.
            if (!origin.known) break;
            features.push_back(point_feature({g.lon_deg, g.lat_deg, g.height_m},
                                             {{"kind", "gnss_fix"},
                                              {"t_s", static_cast<double>(g.header.t_ns) * 1e-9},
                                              {"h_accuracy_m", g.h_accuracy_m},
                                              {"v_accuracy_m", g.v_accuracy_m},
                                              {"satellites", g.satellites},
                                              {"fix_type", g.fix_type}}));
        }
    }
    json doc = {{"type", "FeatureCollection"}, {"features", features}};
    if (origin.known) {
        doc["pednav_origin"] = {
            {"lat_deg", origin.lat_deg}, {"lon_deg", origin.lon_deg}, {"height_m", origin.height_m}};
    } else {
        // Not WGS-84: coordinates are east, north, up metres from the start point.
        doc["crs_local_enu_m"] = true;
    }
    OutFile out(path);
    const std::string text = doc.dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
    std::fwrite(text.data(), 1, text.size(), out.get());
    std::fputc('\n', out.get());
    out.close();
}

void write_gpx(const std::string& path, const std::vector<pn_position_t>& positions, const Origin& origin) {
    OutFile out(path);
    std::FILE* f = out.get();
    std::fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    std::fprintf(f,
                 "<gpx version=\"1.1\" creator=\"pednav\" xmlns=\"http://www.topografix.com/GPX/1/1\"\n"
                 "     xmlns:pednav=\"https://pednav.org/gpx/1\">\n"
                 "  <metadata>\n    <name>pednav track</name>\n");
    if (origin.known) {
        std::fprintf(f, "    <desc>pedestrian dead-reckoning track from lat %.9f lon %.9f</desc>\n",
                     origin.lat_deg, origin.lon_deg);
    } else {
        std::fprintf(f,
                     "    <desc>start point unknown: the track is placed at latitude 0, longitude 0 "
                     "(east/north metres from the start converted as if there)</desc>\n");
    }
    std::fprintf(f, "  </metadata>\n  <trk>\n    <name>pednav track</name>\n    <trkseg>\n");
    const Origin place = origin.known ? origin : Origin{0.0, 0.0, 0.0, true, 0};
    for (size_t i : thinned(positions)) {
        const auto& p = positions[i];
        double lat = 0, lon = 0, h = 0;
        geodesy::enu_to_geodetic(place, p.pos_enu_m, &lat, &lon, &h);
        std::fprintf(f, "      <trkpt lat=\"%.9f\" lon=\"%.9f\"><ele>%.3f</ele>", lat, lon, h);
        if (origin.known && origin.utc_ns_at_zero != 0) {
            std::fprintf(f, "<time>%s</time>", iso_utc(origin.utc_ns_at_zero + p.header.t_ns).c_str());
        }
        std::fprintf(f, "<cmt>t=%.3f s</cmt><type>%s</type>", static_cast<double>(p.header.t_ns) * 1e-9,
                     position_source_name(p.source));
        if (has_floor(p)) std::fprintf(f, "<extensions><pednav:floor>%d</pednav:floor></extensions>", p.floor);
        std::fprintf(f, "</trkpt>\n");
    }
    std::fprintf(f, "    </trkseg>\n  </trk>\n</gpx>\n");
    out.close();
}

const char* position_source_name(int32_t source) {
    switch (source) {
        case PN_POSITION_SOURCE_INERTIAL: return "inertial";
        case PN_POSITION_SOURCE_FUSED: return "fused";
        case PN_POSITION_SOURCE_GNSS: return "gnss";
        case PN_POSITION_SOURCE_MAP: return "map";
        default: return "unknown";
    }
}

}  // namespace pednav::io
