// SPDX-License-Identifier: Apache-2.0
// Outputs in latitude and longitude: the geo track CSV, GeoJSON and GPX read
// back (well-formed, sources and floors kept, coordinates within 1e-7 degree
// of the exact WGS-84 conversion through the origin).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <pednav_geodesy/enu.hpp>

#include "pednav_io/gnss_log.hpp"
#include "pednav_io/text_fields.hpp"
#include "pednav_io/writers.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using namespace pednav::io::test;

namespace {

const Origin kOrigin{48.8566, 2.3522, 50.0, true, 1714557600000000000LL};

// 60 s at 100 Hz: a 200 m radius arc (far enough for the tangent plane to
// matter), inertial, then fused from 20 s, GNSS alone from 40 s; floor 0, none
// for the first second.
std::vector<pn_position_t> make_track() {
    std::vector<pn_position_t> out;
    for (int i = 0; i <= 6000; ++i) {
        pn_position_t p{};
        p.header.struct_size = sizeof p;
        p.header.type = PN_REC_POSITION;
        p.header.t_ns = static_cast<int64_t>(i) * 10000000;
        const double a = i * 1e-4;
        p.pos_enu_m[0] = 200.0 * std::sin(a);
        p.pos_enu_m[1] = 200.0 * (1.0 - std::cos(a));
        p.pos_enu_m[2] = 0.001 * i;
        p.heading_rad = M_PI / 2 - a;
        p.cov_enu_m2[0] = 9.0;
        p.cov_enu_m2[4] = 16.0;
        p.source = i < 2000 ? PN_POSITION_SOURCE_INERTIAL : i < 4000 ? PN_POSITION_SOURCE_FUSED : PN_POSITION_SOURCE_GNSS;
        p.header.flags = i < 100 ? 0u : PN_POSITION_FLAG_HAS_FLOOR;
        out.push_back(p);
    }
    return out;
}

void exact(const pn_position_t& p, double* lat, double* lon, double* h) {
    pednav::geodesy::enu_to_geodetic(kOrigin, p.pos_enu_m, lat, lon, h);
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// XML well-formedness: one root, every element closed in order, attribute
// values quoted, no stray '<' or '&' in text. Returns "" or the problem.
std::string xml_problem(const std::string& text) {
    std::vector<std::string> open;
    bool root_seen = false;
    size_t i = 0;
    while (i < text.size()) {
        if (text[i] != '<') {
            if (text[i] == '&' && text.compare(i, 5, "&amp;") != 0 && text.compare(i, 4, "&lt;") != 0 &&
                text.compare(i, 4, "&gt;") != 0 && text.compare(i, 6, "&quot;") != 0)
                return "bare & at " + std::to_string(i);
            if (open.empty() && !std::isspace(static_cast<unsigned char>(text[i])))
                return "text outside the root at " + std::to_string(i);
            ++i;
            continue;
        }
        const size_t end = text.find('>', i);
        if (end == std::string::npos) return "unclosed tag at " + std::to_string(i);
        std::string tag = text.substr(i + 1, end - i - 1);
        i = end + 1;
        if (tag.empty()) return "empty tag";
        if (tag[0] == '?') continue;  // the XML declaration
        if (tag.find('<') != std::string::npos) return "'<' inside a tag";
        if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "unbalanced quotes in <" + tag + ">";
        if (tag[0] == '/') {
            if (open.empty() || open.back() != tag.substr(1)) return "</" + tag.substr(1) + "> closes nothing open";
            open.pop_back();
            continue;
        }
        const bool self_closing = tag.back() == '/';
        const std::string name = tag.substr(0, tag.find_first_of(" \t\n/"));
        if (open.empty()) {
            if (root_seen) return "a second root <" + name + ">";
            root_seen = true;
        }
        if (!self_closing) open.push_back(name);
    }
    if (!open.empty()) return "<" + open.back() + "> never closed";
    return root_seen ? "" : "no root element";
}

}  // namespace

TEST_CASE("geo track CSV: WGS-84 through the origin, source, floor and sigma per position") {
    const std::string dir = temp_dir();
    const auto track = make_track();
    write_geo_track_csv(dir + "/track_geo.csv", track, kOrigin);
    std::ifstream in(dir + "/track_geo.csv");
    std::string line;
    std::getline(in, line);
    CHECK(line == "t,lat_deg,lon_deg,height_m,heading_deg,floor,source,h_sigma_m");
    size_t rows = 0;
    double worst_deg = 0.0, worst_h = 0.0;
    while (std::getline(in, line)) {
        const auto f = split(line, ',');
        REQUIRE(f.size() == 8);
        const pn_position_t& p = track[rows];
        CHECK(std::llround(std::stod(std::string(f[0])) * 1e9) == p.header.t_ns);
        double lat = 0, lon = 0, h = 0;
        exact(p, &lat, &lon, &h);
        worst_deg = std::max({worst_deg, std::fabs(std::stod(std::string(f[1])) - lat),
                              std::fabs(std::stod(std::string(f[2])) - lon)});
        worst_h = std::max(worst_h, std::fabs(std::stod(std::string(f[3])) - h));
        CHECK(f[5] == (rows < 100 ? "" : "0"));
        CHECK(f[6] == (rows < 2000 ? "inertial" : rows < 4000 ? "fused" : "gnss"));
        CHECK(std::stod(std::string(f[7])) == doctest::Approx(5.0));
        ++rows;
    }
    CHECK(rows == track.size());
    CHECK(worst_deg < 1e-7);
    CHECK(worst_h < 1e-3);
    // The height of the tangent plane falls away from the origin: 200 m off, about 3 mm.
    double lat = 0, lon = 0, h = 0;
    exact(track.back(), &lat, &lon, &h);
    CHECK(h > kOrigin.height_m + 6.0);

    CHECK_THROWS_WITH_AS(write_geo_track_csv(dir + "/nowhere.csv", track, Origin{}),
                         doctest::Contains("latitude and longitude need a geodetic origin"), std::runtime_error);
}

TEST_CASE("GeoJSON: per-vertex sources and floors, source changes, position and GNSS fix points") {
    const std::string dir = temp_dir();
    const auto track = make_track();
    pn_gnss_t fix{};
    fix.header.type = PN_REC_GNSS;
    fix.header.t_ns = 25000000000;
    fix.lat_deg = 48.857;
    fix.lon_deg = 2.353;
    fix.height_m = 51.0;
    fix.h_accuracy_m = 3.0;
    fix.satellites = 9;
    fix.fix_type = PN_GNSS_FIX_AUTONOMOUS;
    const std::vector<pn_gnss_t> fixes{fix};
    GeoJsonExtras extras;
    extras.position_points = true;
    extras.gnss_fixes = &fixes;
    write_geojson(dir + "/t.geojson", track, {}, kOrigin, extras);
    const auto doc = nlohmann::json::parse(slurp(dir + "/t.geojson"));
    const auto& features = doc["features"];
    const auto& line = features[0];
    const auto& coords = line["geometry"]["coordinates"];
    REQUIRE(coords.size() == 601);  // one vertex per 0.1 s
    const auto& sources = line["properties"]["sources"];
    const auto& floors = line["properties"]["floors"];
    REQUIRE(sources.size() == coords.size());
    REQUIRE(floors.size() == coords.size());
    CHECK(sources[0] == "inertial");
    CHECK(sources[300] == "fused");
    CHECK(sources[600] == "gnss");
    CHECK(floors[0].is_null());
    CHECK(floors[10] == 0);
    double worst_deg = 0.0;
    for (size_t k = 0; k < coords.size(); ++k) {
        double lat = 0, lon = 0, h = 0;
        exact(track[k * 10], &lat, &lon, &h);
        worst_deg = std::max({worst_deg, std::fabs(coords[k][1].get<double>() - lat),
                              std::fabs(coords[k][0].get<double>() - lon)});
    }
    CHECK(worst_deg < 1e-7);

    size_t changes = 0, points = 0, gnss = 0;
    for (const auto& f : features) {
        const std::string kind = f["properties"]["kind"];
        if (kind == "source_change") {
            ++changes;
            CHECK(f["properties"]["from_source"] == (changes == 1 ? "inertial" : "fused"));
            CHECK(f["properties"]["to_source"] == (changes == 1 ? "fused" : "gnss"));
            CHECK(f["properties"]["t_s"].get<double>() == doctest::Approx(changes == 1 ? 20.0 : 40.0));
        } else if (kind == "position") {
            ++points;
            if (points == 301) {
                CHECK(f["properties"]["source"] == "fused");
                CHECK(f["properties"]["h_sigma_m"].get<double>() == doctest::Approx(5.0));
                CHECK(f["properties"]["t_s"].get<double>() == doctest::Approx(30.0));
            }
        } else if (kind == "gnss_fix") {
            ++gnss;
            CHECK(f["geometry"]["coordinates"][0].get<double>() == 2.353);
            CHECK(f["geometry"]["coordinates"][1].get<double>() == 48.857);
            CHECK(f["properties"]["satellites"] == 9);
        }
    }
    CHECK(changes == 2);
    CHECK(points == 601);
    CHECK(gnss == 1);
}

TEST_CASE("GPX: well-formed 1.1, source as <type>, floor in the extensions, times from the UTC") {
    const std::string dir = temp_dir();
    const auto track = make_track();
    write_gpx(dir + "/t.gpx", track, kOrigin);
    const std::string text = slurp(dir + "/t.gpx");
    CHECK(xml_problem(text) == "");
    CHECK(xml_problem("<gpx><trk></gpx>") != "");  // the checker can fail
    CHECK(text.find("xmlns=\"http://www.topografix.com/GPX/1/1\"") != std::string::npos);
    size_t count = 0, at = 0;
    double worst_deg = 0.0;
    while ((at = text.find("<trkpt lat=\"", at)) != std::string::npos) {
        double lat = 0, lon = 0;
        std::sscanf(text.c_str() + at, "<trkpt lat=\"%lf\" lon=\"%lf\"", &lat, &lon);
        double elat = 0, elon = 0, eh = 0;
        exact(track[count * 10], &elat, &elon, &eh);
        worst_deg = std::max({worst_deg, std::fabs(lat - elat), std::fabs(lon - elon)});
        const size_t end = text.find("</trkpt>", at);
        const std::string point = text.substr(at, end - at);
        const char* source = count < 200 ? "<type>inertial</type>" : count < 400 ? "<type>fused</type>" : "<type>gnss</type>";
        CHECK(point.find(source) != std::string::npos);
        CHECK((point.find("<extensions><pednav:floor>0</pednav:floor></extensions>") != std::string::npos) ==
              (count >= 10));
        ++count;
        ++at;
    }
    CHECK(count == 601);
    CHECK(worst_deg < 1e-7);
    CHECK(text.find("<time>2024-05-01T10:01:00.000Z</time>") != std::string::npos);  // t = 60 s
}
