// SPDX-License-Identifier: Apache-2.0
// The converters on the shared recordings' maps: feature counts, extents in
// metres, and the walks' own points where a walker can stand.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_indoor_map/geometry_2d.hpp>
#include <pednav_indoor_map/map_check.hpp>
#include <pednav_indoor_map/map_convert.hpp>
#include <pednav_indoor_map/wall_crossings.hpp>

using namespace pednav::indoor_map;

namespace {

const std::string kData = PEDNAV_SHARED_DATA_DIR;

SourceFile source(const std::string& path) {
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "missing shared data file " << path);
    std::stringstream s;
    s << in.rdbuf();
    return {path.substr(path.rfind('/') + 1), s.str()};
}

RairyuuMapFiles biba_files() {
    const std::string d = kData + "/biba-chest-xsens/map/";
    return {source(d + "core.txt"), source(d + "node.txt"), source(d + "link.txt"), source(d + "polygon.txt"),
            source(d + "arrow.txt")};
}

struct Extent {
    double e0 = INFINITY, e1 = -INFINITY, n0 = INFINITY, n1 = -INFINITY;
};
Extent wall_extent(const Map& m, int floor) {
    Extent x;
    for (const auto& w : m.walls)
        if (w.floor == floor)
            for (const Point2& p : {w.a, w.b})
                x.e0 = std::min(x.e0, p.e_m), x.e1 = std::max(x.e1, p.e_m), x.n0 = std::min(x.n0, p.n_m),
                x.n1 = std::max(x.n1, p.n_m);
    return x;
}

double nearest_wall_m(const Map& m, const Point2& p, int floor) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& w : m.walls)
        if (w.floor == floor) d = std::min(d, distance_to_segment(p, w.a, w.b));
    return d;
}

size_t count_kind(const nlohmann::json& doc, const std::string& kind) {
    return static_cast<size_t>(std::count_if(doc["features"].begin(), doc["features"].end(), [&](const auto& f) {
        return f["properties"].value("pednav:kind", "") == kind;
    }));
}

}  // namespace

TEST_CASE("convert humolire: 396 walls of a 70 m x 36 m floor, in HuMoLiRe's metres (y up from the image's bottom edge)") {
    const std::string doc = humolire_to_geojson(source(kData + "/humolire-phone/maps/map_data.json"), {});
    const Map m = read_geojson_map(doc, std::nullopt);
    CHECK(m.walls.size() == 396);
    CHECK(m.zones.empty());
    CHECK(m.floors == std::vector<int>{0});
    CHECK(m.floor_height_m == 4.5);
    const Extent x = wall_extent(m, 0);
    // Pixels 3.97 to 1753.60 across and 3.63 to 911.21 down an image 915
    // pixels tall, at 0.04 m per pixel.
    CHECK(x.e0 == doctest::Approx(0.1589).epsilon(1e-3));
    CHECK(x.e1 == doctest::Approx(70.1442).epsilon(1e-4));
    CHECK(x.n0 == doctest::Approx(36.6 - 36.4486).epsilon(1e-3));
    CHECK(x.n1 == doctest::Approx(36.6 - 0.1452).epsilon(1e-4));
    CHECK(check_map(doc, std::nullopt, {std::nullopt, 0.3}).empty());
}

namespace {
// A walk's start and landmarks as keypoints.json gives them (m), in order.
std::vector<Point2> humolire_keypoints(const std::string& walk) {
    const SourceFile kp_file = source(kData + "/humolire-phone/" + walk + "/keypoints.json");
    const nlohmann::json kp = nlohmann::json::parse(kp_file.text);
    std::vector<Point2> points = {{kp["starting_position"]["x"], kp["starting_position"]["y"]}};
    for (int k = 0; k < kp["count"].get<int>(); ++k)
        points.push_back({kp[std::to_string(k)]["x"], kp[std::to_string(k)]["y"]});
    return points;
}
}  // namespace

TEST_CASE("convert humolire: every walk's start and landmarks stand clear of the walls, inside the building") {
    const std::string doc = humolire_to_geojson(source(kData + "/humolire-phone/maps/map_data.json"), {});
    const Map m = read_geojson_map(doc, std::nullopt);
    for (const char* walk : {"user1_straight", "user1_8_shape", "user1_square_2x", "user3_forward"}) {
        CAPTURE(walk);
        double clearance_m = INFINITY;
        for (const Point2& p : humolire_keypoints(walk)) {  // local metres as they are
            clearance_m = std::min(clearance_m, nearest_wall_m(m, p, 0));
            CHECK(check_map(doc, std::nullopt, {MapStart{p, 0}, 0.5}).empty());
        }
        // The landmarks lie in corridors: the closest is 0.66 m from a wall.
        CHECK(clearance_m > 0.6);
        CHECK(clearance_m < 1.5);
    }
}

TEST_CASE("convert humolire: the closed walks' landmarks join through corridors only with y up") {
    // The square and the figure eight turn left at every corner (the
    // gyroscope's yaw grows by 682 deg over user1_square_2x): with y up their
    // landmarks are joined by straight corridors; with y taken down the image
    // (the walks mirrored) the same lines go through walls.
    const std::string doc = humolire_to_geojson(source(kData + "/humolire-phone/maps/map_data.json"), {});
    const Map m = read_geojson_map(doc, std::nullopt);
    for (const char* walk : {"user1_8_shape", "user1_square_2x"}) {
        CAPTURE(walk);
        std::vector<Point2> up = humolire_keypoints(walk), down = up;
        for (Point2& p : down) p.n_m = 36.6 - p.n_m;
        const std::vector<int> floors(up.size(), 0);
        CHECK(wall_crossings(m, up, floors).empty());
        CHECK(wall_crossings(m, down, floors).size() >= 6);
    }
}

TEST_CASE("convert humolire: the walk's start as local (0, 0), and WGS-84 around an origin") {
    MapConversion c;
    c.start_source_m = {{7.147, 6.154}};
    const std::string local = humolire_to_geojson(source(kData + "/humolire-phone/maps/map_data.json"), c);
    const Map m = read_geojson_map(local, std::nullopt);
    REQUIRE(m.landmarks.size() == 1);
    CHECK(m.landmarks[0].p.e_m == 0.0);
    CHECK(m.landmarks[0].p.n_m == 0.0);
    CHECK(wall_extent(m, 0).e0 == doctest::Approx(0.1589 - 7.147).epsilon(1e-3));
    CHECK(wall_extent(m, 0).n1 == doctest::Approx(36.6 - 0.1452 - 6.154).epsilon(1e-3));
    c.origin = pednav::geodesy::GeodeticPoint{47.2, -1.55, 40.0};
    const std::string wgs84 = humolire_to_geojson(source(kData + "/humolire-phone/maps/map_data.json"), c);
    CHECK(nlohmann::json::parse(wgs84)["pednav:origin"] == nlohmann::json::array({-1.55, 47.2, 40.0}));
    const Map g = read_geojson_map(wgs84, std::nullopt);
    REQUIRE(g.walls.size() == m.walls.size());
    for (size_t k = 0; k < g.walls.size(); k += 37) {
        // Local metres are written to 0.1 mm.
        CHECK(std::fabs(g.walls[k].a.e_m - m.walls[k].a.e_m) < 0.6e-4);
        CHECK(std::fabs(g.walls[k].b.n_m - m.walls[k].b.n_m) < 0.6e-4);
    }
}

TEST_CASE("convert biba: four floors of walls, no-particle zones, stairs arrows and areas, the start at (0, 0)") {
    const std::string doc = rairyuu_to_geojson(biba_files(), {});
    const nlohmann::json j = nlohmann::json::parse(doc);
    CHECK(count_kind(j, "wall") == 525);
    CHECK(count_kind(j, "no_particles") == 43);
    CHECK(count_kind(j, "stairs") == 13 + 10);  // 13 arrows; 9 floor-change areas, one of them reaching two floors
    CHECK(count_kind(j, "landmark") == 1);
    CHECK(j["features"].size() == 525 + 43 + 23 + 1 + 10);  // 10 floor-change areas no arrow ends in: kept, kindless
    const Map m = read_geojson_map(doc, std::nullopt);
    // Layers 0 to 3, the start on layer 1: floors -1 to 2.
    CHECK(m.floors == std::vector<int>{-1, 0, 1, 2});
    CHECK(m.floor_height_m == 4.5);
    const Extent x = wall_extent(m, 0);
    // Layer 1 spans pixels 7 to 1739 across, 9 to 863 down, at 0.33167 m per pixel, around the start (637.4, 62.2) px.
    CHECK(x.e1 - x.e0 == doctest::Approx(574.4).epsilon(1e-3));
    CHECK(x.n1 - x.n0 == doctest::Approx(283.3).epsilon(1e-3));
    CHECK(x.e0 < 0);
    CHECK(x.e1 > 0);
    CHECK(x.n1 > 0);  // 62 px below the top of the image
    CHECK(x.n1 < 21);
    REQUIRE(m.landmarks.size() == 1);
    CHECK(m.landmarks[0].p.e_m == 0.0);
    CHECK(m.landmarks[0].p.n_m == 0.0);
    // Arrow 10 climbs from layer 1 at (776.875, 812.375) px to layer 2 at (769.125, 795.677) px.
    const auto up = std::find_if(m.connectors.begin(), m.connectors.end(), [&](const Connector& c) {
        return j["features"][c.feature]["properties"].value("source", "") == "arrow 10";
    });
    REQUIRE(up != m.connectors.end());
    CHECK(up->floor == 0);
    CHECK(up->floor_to == 1);
    CHECK(up->direction == ConnectorDirection::up);
    CHECK(std::fabs(up->area[1].e_m - up->area[0].e_m - (769.125 - 776.875) * 0.33167) < 1.1e-4);
    CHECK(std::fabs(up->area[1].n_m - up->area[0].n_m - (812.375 - 795.6765045) * 0.33167) < 1.1e-4);
}

TEST_CASE("convert biba: the map checks clean and the routes' start lies inside it, clear of walls and voids") {
    const std::string doc = rairyuu_to_geojson(biba_files(), {});
    CHECK(check_map(doc, std::nullopt, {MapStart{{0, 0}, 0}, 0.5}).empty());
    const Map m = read_geojson_map(doc, std::nullopt);
    CHECK(nearest_wall_m(m, {0, 0}, 0) == doctest::Approx(8.795 * 0.33167).epsilon(1e-3));
    // 20 m west the start would be outside the walls of its floor.
    CHECK(!check_map(doc, std::nullopt, {MapStart{{-220, 0}, 0}, 0.5}).empty());
}

TEST_CASE("convert: bad sources are named by file and line or JSON pointer") {
    auto error = [](auto&& f) {
        try {
            f();
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    CHECK(error([] {
              humolire_to_geojson({"m.json", R"({"scale": 0.04, "y_range": [0, 10], "links": [{"node0": {"x": 1, "y": 2}}]})"}, {});
          }) == "m.json:/links/0/node0/layer: layer is missing");
    CHECK(error([] { humolire_to_geojson({"m.json", R"({"scale": 0.04, "links": []})"}, {}); }) ==
          "m.json:/y_range: y_range is missing");
    CHECK(error([] { humolire_to_geojson({"m.json", R"({"scale": -1, "links": []})"}, {}); }) ==
          "m.json:/scale: the scale (m per pixel) must be positive");
    // Found by fuzz_map_humolire: a number beyond a double escaped as nlohmann's out_of_range.
    CHECK(error([] {
              try {
                  humolire_to_geojson({"m.json", R"({"scale": 1e400, "links": []})"}, {});
              } catch (const std::runtime_error&) {
                  throw;
              } catch (...) {
                  throw std::logic_error("not a std::runtime_error");
              }
          }) == "m.json:/scale: the number at /scale is out of range (not a finite double)");
    RairyuuMapFiles f = biba_files();
    f.link.text += "\n900,0,25,99999\n";  // after its 525 links
    CHECK(error([&] { rairyuu_to_geojson(f, {}); }) == "link.txt:527: node 99999 is not in node.txt");
    f = biba_files();
    f.node.text = "id,layer,x,y\n0,7,1,1\n";
    CHECK(error([&] { rairyuu_to_geojson(f, {}); }) == "node.txt:2: layer 7 is not one of core.txt's 4 floors");
    f = biba_files();
    f.arrow.text = "id,type,nodeID0,nodeID1\n0,5,567,568\n";
    CHECK(error([&] { rairyuu_to_geojson(f, {}); }) ==
          "arrow.txt:2: arrow type 5 is not 0 (from below), 1 (from above) or 2 (either)");
}
