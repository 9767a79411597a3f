// SPDX-License-Identifier: Apache-2.0
// Writers: write, parse back, compare.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <pednav_geodesy/enu.hpp>

#include "pednav_io/text_fields.hpp"
#include "pednav_io/writers.hpp"
#include "test_util.hpp"

using namespace pednav::io;
using pednav::geodesy::geodetic_to_enu;
using namespace pednav::io::test;

namespace {

// A 20 s walk north-east at 1 m/s, 100 Hz, climbing to floor 1 at t = 10 s.
std::vector<pn_position_t> make_track() {
    std::vector<pn_position_t> out;
    for (int i = 0; i <= 2000; ++i) {
        pn_position_t p{};
        p.header.struct_size = sizeof p;
        p.header.type = PN_REC_POSITION;
        p.header.t_ns = static_cast<int64_t>(i) * 10000000;
        const double t = i * 0.01;
        p.pos_enu_m[0] = t * std::sqrt(0.5);
        p.pos_enu_m[1] = t * std::sqrt(0.5);
        p.pos_enu_m[2] = t < 10 ? 0.0 : 3.5;
        p.heading_rad = i < 1000 ? M_PI / 4 : -M_PI / 4;  // 45 deg, then 315 deg
        p.cov_enu_m2[0] = 0.01 * t;
        p.cov_enu_m2[1] = p.cov_enu_m2[3] = 0.001;
        p.cov_enu_m2[4] = 0.02 * t;
        p.cov_enu_m2[8] = 0.5;
        p.floor = t < 10 ? 0 : 1;
        p.header.flags = i < 5 ? 0u : PN_POSITION_FLAG_HAS_FLOOR;
        out.push_back(p);
    }
    return out;
}

std::vector<pn_stride_t> make_strides() {
    std::vector<pn_stride_t> out;
    for (int k = 0; k < 14; ++k) {
        pn_stride_t s{};
        s.header.struct_size = sizeof s;
        s.header.type = PN_REC_STRIDE;
        s.header.t_ns = static_cast<int64_t>(k + 1) * 1400000000;
        s.t_start_ns = static_cast<int64_t>(k) * 1400000000;
        s.displacement_enu_m[0] = s.displacement_enu_m[1] = 1.4 * std::sqrt(0.5);
        s.length_m = 1.4;
        s.heading_change_rad = 0.01 * k;
        s.cov_displacement_m2[0] = s.cov_displacement_m2[4] = 0.0004;
        s.stride_class = k == 7 ? PN_STRIDE_CLASS_STAIRS_UP : PN_STRIDE_CLASS_LEVEL;
        s.index = k;
        out.push_back(s);
    }
    return out;
}

// Every field of every line, split as the readers split them.
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(in, line)) {
        const std::vector<std::string_view> fields = split(line, ',');
        rows.emplace_back(fields.begin(), fields.end());
    }
    return rows;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TEST_CASE("track CSV round trip") {
    const std::string dir = temp_dir();
    const auto track = make_track();
    write_track_csv(dir + "/track.csv", track);
    const auto rows = read_csv(dir + "/track.csv");
    REQUIRE(rows.size() == track.size() + 1);
    CHECK(rows[0] == std::vector<std::string>{"t", "x", "y", "z", "heading_deg", "floor", "cov_xx", "cov_xy",
                                              "cov_yy", "cov_zz"});
    for (size_t i = 0; i < track.size(); i += 97) {
        const auto& r = rows[i + 1];
        REQUIRE(r.size() == 10);
        CHECK(std::llround(std::stod(r[0]) * 1e9) == track[i].header.t_ns);
        CHECK(std::fabs(std::stod(r[1]) - track[i].pos_enu_m[0]) < 1e-6);  // printed to the micrometre
        CHECK(std::stod(r[3]) == doctest::Approx(track[i].pos_enu_m[2]));
        CHECK(std::stod(r[4]) == doctest::Approx(i < 1000 ? 45.0 : 315.0));  // clockwise from north, [0, 360)
        CHECK(r[5] == (i < 5 ? "" : std::to_string(track[i].floor)));
        CHECK(std::stod(r[6]) == doctest::Approx(track[i].cov_enu_m2[0]));
        CHECK(std::stod(r[7]) == doctest::Approx(0.001));
        CHECK(std::stod(r[8]) == doctest::Approx(track[i].cov_enu_m2[4]));
        CHECK(std::stod(r[9]) == doctest::Approx(0.5));
    }
}

TEST_CASE("steps CSV round trip") {
    const std::string dir = temp_dir();
    const auto strides = make_strides();
    write_steps_csv(dir + "/steps.csv", strides);
    const auto rows = read_csv(dir + "/steps.csv");
    REQUIRE(rows.size() == strides.size() + 1);
    CHECK(rows[0][0] == "index");
    CHECK(rows[0][8] == "class");
    CHECK(rows[8][8] == "stairs_up");
    CHECK(rows[1][8] == "level");
    CHECK(std::stod(rows[3][2]) == doctest::Approx(4.2));
    CHECK(std::stod(rows[3][6]) == doctest::Approx(1.4));
    CHECK(std::stod(rows[4][7]) == doctest::Approx(0.03 * 57.29577951308232));
}

TEST_CASE("GeoJSON: WGS-84 with an origin, local metres without") {
    const std::string dir = temp_dir();
    const auto track = make_track();
    const auto strides = make_strides();
    const Origin origin{47.0, 8.0, 400.0, true, 0};
    write_geojson(dir + "/track.geojson", track, strides, origin);
    const auto doc = nlohmann::json::parse(slurp(dir + "/track.geojson"));
    CHECK(doc["type"] == "FeatureCollection");
    const auto& features = doc["features"];
    REQUIRE(features.size() == 1 + strides.size() + 1);
    const auto& line = features[0];
    CHECK(line["geometry"]["type"] == "LineString");
    const auto& coords = line["geometry"]["coordinates"];
    CHECK(coords.size() == 201);  // thinned to 10 per second
    CHECK(line["properties"]["times_s"].size() == coords.size());
    // Back to ENU: the last point is 20 s * 1 m/s along north-east.
    const auto& last = coords.back();
    double enu[3];
    geodetic_to_enu(origin, last[1].get<double>(), last[0].get<double>(), last[2].get<double>(), enu);
    CHECK(enu[0] == doctest::Approx(20.0 * std::sqrt(0.5)).epsilon(1e-6));
    CHECK(enu[1] == doctest::Approx(20.0 * std::sqrt(0.5)).epsilon(1e-6));
    CHECK(enu[2] == doctest::Approx(3.5).epsilon(1e-6));
    // A step point: the position at the stride's end time.
    const auto& step = features[3];
    CHECK(step["properties"]["kind"] == "step");
    CHECK(step["properties"]["index"] == 2);
    CHECK(step["properties"]["t_s"].get<double>() == doctest::Approx(4.2));
    geodetic_to_enu(origin, step["geometry"]["coordinates"][1].get<double>(),
                    step["geometry"]["coordinates"][0].get<double>(), 400.0, enu);
    CHECK(std::hypot(enu[0], enu[1]) == doctest::Approx(4.2).epsilon(1e-6));
    const auto& floor = features.back();
    CHECK(floor["properties"]["kind"] == "floor_change");
    CHECK(floor["properties"]["from_floor"] == 0);
    CHECK(floor["properties"]["to_floor"] == 1);
    CHECK(floor["properties"]["t_s"].get<double>() == doctest::Approx(10.0));

    write_geojson(dir + "/local.geojson", track, strides, Origin{});
    const auto local = nlohmann::json::parse(slurp(dir + "/local.geojson"));
    CHECK(local["crs_local_enu_m"] == true);
    const auto& lc = local["features"][0]["geometry"]["coordinates"].back();
    CHECK(lc[0].get<double>() == doctest::Approx(20.0 * std::sqrt(0.5)));
    CHECK(lc[2].get<double>() == doctest::Approx(3.5));
}

TEST_CASE("GPX: track points back to ENU, times when the UTC is known") {
    const std::string dir = temp_dir();
    const auto track = make_track();
    const Origin origin{-33.9, 151.2, 10.0, true, 1700000000000000000LL};
    write_gpx(dir + "/track.gpx", track, origin);
    const std::string text = slurp(dir + "/track.gpx");
    CHECK(text.find("<gpx version=\"1.1\"") != std::string::npos);
    size_t count = 0, at = 0;
    double lat = 0, lon = 0, ele = 0;
    while ((at = text.find("<trkpt lat=\"", at)) != std::string::npos) {
        ++count;
        std::sscanf(text.c_str() + at, "<trkpt lat=\"%lf\" lon=\"%lf\"><ele>%lf</ele>", &lat, &lon, &ele);
        ++at;
    }
    CHECK(count == 201);
    double enu[3];
    geodetic_to_enu(origin, lat, lon, ele, enu);
    CHECK(std::fabs(enu[0] - 20.0 * std::sqrt(0.5)) < 1e-3);  // 1e-9 degree is 0.1 mm
    CHECK(std::fabs(enu[1] - 20.0 * std::sqrt(0.5)) < 1e-3);
    CHECK(std::fabs(enu[2] - 3.5) < 1e-3);
    CHECK(text.find("<time>2023-11-14T22:13:20.000Z</time>") != std::string::npos);
    CHECK(text.find("<time>2023-11-14T22:13:40.000Z</time>") != std::string::npos);

    write_gpx(dir + "/nowhere.gpx", track, Origin{});
    const std::string nowhere = slurp(dir + "/nowhere.gpx");
    CHECK(nowhere.find("start point unknown") != std::string::npos);
    CHECK(nowhere.find("<time>") == std::string::npos);
}

TEST_CASE("run summary JSON") {
    const std::string dir = temp_dir();
    std::ostringstream f;
    f << "t,ax,ay,az,gx,gy,gz\n";
    for (int i = 0; i < 100; ++i) f << i * 0.01 << ",0,0,9.8,0,0,0\n";
    f << "1.5,0,0,x,0,0,0\n";
    const SensorLog log = read_sensor_file(write_file(dir, "in.csv", f.str()));
    const std::string describe =
        R"({"engine":{"version":"0.1.0"},"pipeline":{"mount":"foot","stages":[{"plugin":"a","version":"1"}]},"counters":{"records_in":100}})";
    const auto track = make_track();
    const auto strides = make_strides();
    const auto s = run_summary_json(log, describe, track, strides, {"one warning"});
    CHECK(s["format"] == "pednav-run-summary/1");
    CHECK(s["input"]["format"] == "pednav-csv");
    CHECK(s["input"]["streams"][0]["name"] == "accel");
    CHECK(s["input"]["streams"][0]["count"] == 100);
    CHECK(s["input"]["streams"][0]["bad_rows"] == 1);
    CHECK(s["input"]["issues"][0]["line"] == 102);
    CHECK(s["pipeline"]["mount"] == "foot");
    CHECK(s["engine"]["version"] == "0.1.0");
    CHECK(s["samples"]["imu"] == 100);
    CHECK(s["steps"] == 14);
    CHECK(s["distance_m"].get<double>() == doctest::Approx(20.0));  // horizontal length of the track
    CHECK(s["stride_length_sum_m"].get<double>() == doctest::Approx(14 * 1.4));
    CHECK(s["duration_s"].get<double>() == doctest::Approx(20.0));
    CHECK(s["floors"] == nlohmann::json::array({0, 1}));
    CHECK(s["warnings"][0] == "one warning");
    CHECK(s["counters"]["records_in"] == 100);
}
