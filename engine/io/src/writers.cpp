// SPDX-License-Identifier: Apache-2.0
// Track and step CSVs, GeoJSON and GPX.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <stdexcept>

#include "pednav_io/writers.hpp"

namespace pednav::io {

namespace {

constexpr double kRadToDeg = 57.29577951308232;
// GeoJSON and GPX keep at most one position per this interval (plus the last).
constexpr int64_t kThinInterval_ns = 100000000;

class OutFile {
public:
    explicit OutFile(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "w")) {
        if (file_ == nullptr) throw std::runtime_error(path + ": cannot open for writing");
    }
    ~OutFile() {
        if (file_ != nullptr) std::fclose(file_);
    }
    OutFile(const OutFile&) = delete;
    OutFile& operator=(const OutFile&) = delete;
    std::FILE* get() { return file_; }
    void close() {
        const bool failed = std::ferror(file_) != 0;
        const int rc = std::fclose(file_);
        file_ = nullptr;
        if (failed || rc != 0) throw std::runtime_error(path_ + ": write failed");
    }

private:
    std::string path_;
    std::FILE* file_;
};

double heading_deg(double heading_rad) {
    double d = std::fmod(heading_rad * kRadToDeg, 360.0);
    if (d < 0) d += 360.0;
    return d;
}

const char* class_name(int32_t c) {
    switch (c) {
        case PN_STRIDE_CLASS_LEVEL: return "level";
        case PN_STRIDE_CLASS_STAIRS_UP: return "stairs_up";
        case PN_STRIDE_CLASS_STAIRS_DOWN: return "stairs_down";
        default: return "unknown";
    }
}

bool has_floor(const pn_position_t& p) { return (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) != 0; }

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

std::string iso_utc(int64_t utc_ns) {
    const std::time_t seconds = static_cast<std::time_t>(utc_ns / 1000000000);
    const int millis = static_cast<int>((utc_ns % 1000000000) / 1000000);
    std::tm tm{};
    gmtime_r(&seconds, &tm);
    char text[96];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                  tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, millis);
    return text;
}

}  // namespace

void write_track_csv(const std::string& path, const std::vector<pn_position_t>& positions) {
    OutFile out(path);
    std::fprintf(out.get(), "t,x,y,z,heading_deg,floor,cov_xx,cov_xy,cov_yy,cov_zz\n");
    for (const auto& p : positions) {
        char floor[16] = "";
        if (has_floor(p)) std::snprintf(floor, sizeof floor, "%d", p.floor);
        std::fprintf(out.get(), "%.9f,%.6f,%.6f,%.6f,%.4f,%s,%.9g,%.9g,%.9g,%.9g\n",
                     static_cast<double>(p.header.t_ns) * 1e-9, p.pos_enu_m[0], p.pos_enu_m[1],
                     p.pos_enu_m[2], heading_deg(p.heading_rad), floor, p.cov_enu_m2[0], p.cov_enu_m2[1],
                     p.cov_enu_m2[4], p.cov_enu_m2[8]);
    }
    out.close();
}

void write_steps_csv(const std::string& path, const std::vector<pn_stride_t>& strides) {
    OutFile out(path);
    std::fprintf(
        out.get(),
        "index,t_start,t_end,dx,dy,dz,length_m,heading_change_deg,class,cov_xx,cov_xy,cov_yy,cov_zz\n");
    for (const auto& s : strides) {
        std::fprintf(out.get(), "%d,%.9f,%.9f,%.6f,%.6f,%.6f,%.6f,%.4f,%s,%.9g,%.9g,%.9g,%.9g\n", s.index,
                     static_cast<double>(s.t_start_ns) * 1e-9, static_cast<double>(s.header.t_ns) * 1e-9,
                     s.displacement_enu_m[0], s.displacement_enu_m[1], s.displacement_enu_m[2], s.length_m,
                     s.heading_change_rad * kRadToDeg, class_name(s.stride_class), s.cov_displacement_m2[0],
                     s.cov_displacement_m2[1], s.cov_displacement_m2[4], s.cov_displacement_m2[8]);
    }
    out.close();
}

void write_geojson(const std::string& path, const std::vector<pn_position_t>& positions,
                   const std::vector<pn_stride_t>& strides, const Origin& origin) {
    using nlohmann::json;
    json features = json::array();
    json line = json::array();
    json times = json::array();
    for (size_t i : thinned(positions)) {
        line.push_back(coordinates(positions[i].pos_enu_m, origin));
        times.push_back(static_cast<double>(positions[i].header.t_ns) * 1e-9);
    }
    if (!positions.empty()) {
        features.push_back({{"type", "Feature"},
                            {"geometry", {{"type", "LineString"}, {"coordinates", line}}},
                            {"properties",
                             {{"kind", "track"},
                              {"times_s", times},
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
    json doc = {{"type", "FeatureCollection"}, {"features", features}};
    if (origin.known) {
        doc["pednav_origin"] = {
            {"lat_deg", origin.lat_deg}, {"lon_deg", origin.lon_deg}, {"height_m", origin.height_m}};
    } else {
        // Not WGS-84: coordinates are east, north, up metres from the start point.
        doc["crs_local_enu_m"] = true;
    }
    OutFile out(path);
    const std::string text = doc.dump(1);
    std::fwrite(text.data(), 1, text.size(), out.get());
    std::fputc('\n', out.get());
    out.close();
}

void write_gpx(const std::string& path, const std::vector<pn_position_t>& positions, const Origin& origin) {
    OutFile out(path);
    std::FILE* f = out.get();
    std::fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    std::fprintf(f,
                 "<gpx version=\"1.1\" creator=\"pednav\" xmlns=\"http://www.topografix.com/GPX/1/1\">\n"
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
        std::fprintf(f, "<cmt>t=%.3f s</cmt></trkpt>\n", static_cast<double>(p.header.t_ns) * 1e-9);
    }
    std::fprintf(f, "    </trkseg>\n  </trk>\n</gpx>\n");
    out.close();
}

}  // namespace pednav::io
