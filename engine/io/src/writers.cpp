// SPDX-License-Identifier: Apache-2.0
// GeoJSON and GPX.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
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

// Positions read in order: a vector's or a PositionLog's.
struct Positions {
    size_t size;
    std::function<void(const std::function<void(const pn_position_t&)>&)> for_each;
};

Positions positions_of(const std::vector<pn_position_t>& v) {
    return {v.size(), [&v](const std::function<void(const pn_position_t&)>& f) {
                for (const auto& p : v) f(p);
            }};
}

Positions positions_of(const PositionLog& log) {
    return {log.size(), [&log](const std::function<void(const pn_position_t&)>& f) { log.for_each(f); }};
}

// The positions GeoJSON and GPX draw: at most one per kThinInterval_ns, each
// floor change, and the last.
class Thinning {
public:
    explicit Thinning(size_t count) : count_(count) {}
    bool keep(const pn_position_t& p) {
        const bool floor_changed = index_ > 0 && has_floor(p) && p.floor != previous_floor_;
        const bool kept = index_ == 0 || index_ + 1 == count_ || floor_changed ||
                          p.header.t_ns - kept_t_ns_ >= kThinInterval_ns;
        if (kept) kept_t_ns_ = p.header.t_ns;
        previous_floor_ = p.floor;
        ++index_;
        return kept;
    }

private:
    size_t count_;
    size_t index_ = 0;
    int64_t kept_t_ns_ = 0;
    int32_t previous_floor_ = 0;
};

nlohmann::json coordinates(const double enu[3], const Origin& origin) {
    if (!origin.known) return {enu[0], enu[1], enu[2]};
    double lat = 0, lon = 0, h = 0;
    geodesy::enu_to_geodetic(origin, enu, &lat, &lon, &h);
    return {lon, lat, h};
}

}  // namespace

namespace {

void write_geojson_of(const std::string& path, const Positions& positions, const std::vector<pn_stride_t>& strides,
                      const Origin& origin, const GeoJsonExtras& extras) {
    using nlohmann::json;
    json features = json::array();
    json line = json::array();
    json times = json::array(), sources = json::array(), floors = json::array();
    json position_points = json::array(), floor_changes = json::array(), source_changes = json::array();
    // Each stride's point is the last position at or before its time (the first when none is):
    // the positions and the strides, each in time order, walked together.
    std::vector<size_t> by_time(strides.size());
    for (size_t k = 0; k < by_time.size(); ++k) by_time[k] = k;
    std::stable_sort(by_time.begin(), by_time.end(),
                     [&](size_t a, size_t b) { return strides[a].header.t_ns < strides[b].header.t_ns; });
    std::vector<pn_position_t> stride_at(strides.size());
    size_t next_stride = 0;
    Thinning thinning(positions.size);
    bool have_previous = false, have_floor = false;
    pn_position_t previous{};
    int32_t last_floor = 0;
    positions.for_each([&](const pn_position_t& p) {
        while (next_stride < by_time.size() && p.header.t_ns > strides[by_time[next_stride]].header.t_ns)
            stride_at[by_time[next_stride++]] = have_previous ? previous : p;
        if (thinning.keep(p)) {
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
        if (has_floor(p)) {
            if (have_floor && p.floor != last_floor) {
                floor_changes.push_back(
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
        if (have_previous && p.source != previous.source) {
            source_changes.push_back(point_feature(coordinates(p.pos_enu_m, origin),
                                                   {{"kind", "source_change"},
                                                    {"t_s", static_cast<double>(p.header.t_ns) * 1e-9},
                                                    {"from_source", position_source_name(previous.source)},
                                                    {"to_source", position_source_name(p.source)}}));
        }
        previous = p;
        have_previous = true;
    });
    while (next_stride < by_time.size()) stride_at[by_time[next_stride++]] = previous;
    if (positions.size > 0) {
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
    for (size_t k = 0; k < strides.size() && positions.size > 0; ++k) {
        const pn_stride_t& s = strides[k];
        features.push_back(
            {{"type", "Feature"},
             {"geometry", {{"type", "Point"}, {"coordinates", coordinates(stride_at[k].pos_enu_m, origin)}}},
             {"properties",
              {{"kind", "step"},
               {"index", s.index},
               {"t_s", static_cast<double>(s.header.t_ns) * 1e-9},
               {"t_start_s", static_cast<double>(s.t_start_ns) * 1e-9},
               {"length_m", s.length_m},
               {"heading_change_deg", s.heading_change_rad * kRadToDeg},
               {"class", class_name(s.stride_class)}}}});
    }
    for (auto& f : floor_changes) features.push_back(std::move(f));
    for (auto& f : source_changes) features.push_back(std::move(f));
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

void write_gpx_of(const std::string& path, const Positions& positions, const Origin& origin) {
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
    Thinning thinning(positions.size);
    positions.for_each([&](const pn_position_t& p) {
        if (!thinning.keep(p)) return;
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
    });
    std::fprintf(f, "    </trkseg>\n  </trk>\n</gpx>\n");
    out.close();
}

}  // namespace

void write_geojson(const std::string& path, const std::vector<pn_position_t>& positions,
                   const std::vector<pn_stride_t>& strides, const Origin& origin, const GeoJsonExtras& extras) {
    write_geojson_of(path, positions_of(positions), strides, origin, extras);
}

void write_geojson(const std::string& path, const PositionLog& positions, const std::vector<pn_stride_t>& strides,
                   const Origin& origin, const GeoJsonExtras& extras) {
    write_geojson_of(path, positions_of(positions), strides, origin, extras);
}

void write_gpx(const std::string& path, const std::vector<pn_position_t>& positions, const Origin& origin) {
    write_gpx_of(path, positions_of(positions), origin);
}

void write_gpx(const std::string& path, const PositionLog& positions, const Origin& origin) {
    write_gpx_of(path, positions_of(positions), origin);
}

void write_geo_track_csv(const std::string& path, const PositionLog& positions, const Origin& origin) {
    GeoTrackCsvWriter out(path, origin);
    positions.for_each([&](const pn_position_t& p) { out.add(p); });
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
