// SPDX-License-Identifier: Apache-2.0
// What the app sets besides samples: each call either takes effect or says
// why it cannot (PN_E_BAD_STATE, PN_E_UNSUPPORTED, PN_E_INVALID_ARGUMENT) and
// changes nothing; settings made before the first push survive a reset.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

const std::vector<StageSpec> kPipeline = {{"step_detector", "org.pednav.test.counting_steps"},
                                          {"attitude_estimator", "org.pednav.test.fixed_heading"},
                                          {"position_filter", "org.pednav.test.step_counter"}};

pn_position_t last_position(const Engine& e) {
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    REQUIRE(!pos.empty());
    return pos.back().position;
}

constexpr double kPi = 3.14159265358979323846;

}  // namespace

TEST_CASE("set_start after the first push is refused and changes nothing") {
    Engine e(make_config(kPipeline), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    const double start[3] = {5.0, 0.0, 0.0};
    REQUIRE(pn_engine_set_start(e.get(), start, NAN, &err) == PN_OK);
    REQUIRE(push(e, walk(0, 11)) == PN_OK);  // one 0.7 m step north (the fixed heading) at sample 10
    const double moved[3] = {100.0, 0.0, 0.0};
    CHECK(pn_engine_set_start(e.get(), moved, NAN, &err) == PN_E_BAD_STATE);
    CHECK(std::string(err.where) == "set_start");
    CHECK(contains(err.message, "before the first push"));
    REQUIRE(push(e, walk(11, 10)) == PN_OK);
    pn_position_t p = last_position(e);
    CHECK(p.pos_enu_m[0] == 5.0);  // still from the first start
    CHECK(p.pos_enu_m[1] == doctest::Approx(2 * 0.7));
    // A reset gives the fresh plugins the start again, and set_start works again.
    REQUIRE(pn_engine_reset(e.get(), &err) == PN_OK);
    REQUIRE(push(e, walk(0, 11)) == PN_OK);
    p = last_position(e);
    CHECK(p.pos_enu_m[0] == 5.0);
    CHECK(p.pos_enu_m[1] == doctest::Approx(0.7));
    REQUIRE(pn_engine_reset(e.get(), &err) == PN_OK);
    CHECK(pn_engine_set_start(e.get(), moved, NAN, &err) == PN_OK);
}

TEST_CASE("set_output_mask refuses bits of types that are never outputs") {
    Engine e(make_config(kPipeline), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    CHECK(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_STRIDE)) == PN_OK);
    CHECK(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_STRIDE) | (uint64_t(1) << 40)) == PN_E_INVALID_ARGUMENT);
    CHECK(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_IMU)) == PN_E_INVALID_ARGUMENT);
    CHECK(pn_engine_set_output_mask(e.get(), 1) == PN_E_INVALID_ARGUMENT);  // bit 0 is no type
    REQUIRE(push(e, walk(0, 31)) == PN_OK);
    const auto out = e.poll_all();
    CHECK(out.size() == 3);  // the mask of the call that succeeded: strides only
    CHECK(of_type(out, PN_REC_STRIDE).size() == 3);
}

TEST_CASE("set_attitude reaches the attitude estimator, before the first push only") {
    Engine e(make_config(kPipeline), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    const double not_unit[4] = {1.0, 1.0, 0.0, 0.0};
    CHECK(pn_engine_set_attitude(e.get(), not_unit, &err) == PN_E_INVALID_ARGUMENT);
    // Heading 90 deg (east): yaw 0 about Up from east, the identity quaternion.
    const double east[4] = {1.0, 0.0, 0.0, 0.0};
    REQUIRE(pn_engine_set_attitude(e.get(), east, &err) == PN_OK);
    REQUIRE(push(e, walk(0, 21)) == PN_OK);
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    REQUIRE(pos.size() == 2);
    CHECK(pos.back().position.heading_rad == doctest::Approx(kPi / 2));
    CHECK(pos.back().position.pos_enu_m[0] == doctest::Approx(1.4));
    CHECK(pn_engine_set_attitude(e.get(), east, &err) == PN_E_BAD_STATE);
    REQUIRE(pn_engine_reset(e.get(), &err) == PN_OK);  // given again after the reset
    REQUIRE(push(e, walk(0, 11)) == PN_OK);
    CHECK(last_position(e).pos_enu_m[0] == doctest::Approx(0.7));
}

TEST_CASE("set_attitude without an estimator that takes one is unsupported") {
    Engine e(make_config({{"step_detector", "org.pednav.test.counting_steps"}}), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    const double q[4] = {1.0, 0.0, 0.0, 0.0};
    CHECK(pn_engine_set_attitude(e.get(), q, &err) == PN_E_UNSUPPORTED);
    CHECK(contains(err.message, "no attitude estimator"));
}

TEST_CASE("reconfigure changes a stage's params live, or says why not") {
    Engine e(make_config(kPipeline), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    REQUIRE(push(e, walk(0, 21)) == PN_OK);  // steps at samples 10 and 20 are out once 21 is in
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 2);
    const std::string every5 = R"({"every_n": 5})";
    REQUIRE(pn_engine_reconfigure(e.get(), "step_detector", every5.c_str(), 0, &err) == PN_OK);
    // Samples 20..39 are processed (40 waits), counted 21..40: steps at counts 25, 30, 35, 40.
    REQUIRE(push(e, walk(21, 20)) == PN_OK);
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 4);

    CHECK(pn_engine_reconfigure(e.get(), "foot/step_detector", R"({"every_m": 5})", 0, &err) == PN_E_INVALID_CONFIG);
    CHECK(std::string(err.where) == "/params/every_m");
    CHECK(pn_engine_reconfigure(e.get(), "step_detector", R"({"latency_samples": 3})", 0, &err) == PN_E_UNSUPPORTED);
    CHECK(pn_engine_reconfigure(e.get(), "attitude_estimator", "{}", 0, &err) == PN_E_UNSUPPORTED);
    CHECK(pn_engine_reconfigure(e.get(), "map_matcher", "{}", 0, &err) == PN_E_NOT_FOUND);
    // The live params survive a reset: counts 5, 10, 15, 20.
    REQUIRE(pn_engine_reset(e.get(), &err) == PN_OK);
    REQUIRE(push(e, walk(0, 21)) == PN_OK);
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 4);
}

TEST_CASE("maps: no map matcher, a config map file that is missing, one that loads") {
    pn_error_t err = make_error();
    {
        Engine e(make_config(kPipeline), {fixture_dir("good")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        CHECK(pn_engine_load_map(e.get(), "pednav.map/1", "{}", 2, &err) == PN_E_UNSUPPORTED);
        CHECK(contains(err.message, "no map matcher"));
    }
    std::vector<StageSpec> with_map = kPipeline;
    with_map.push_back({"map_matcher", "org.pednav.test.map_anchor"});
    const std::vector<std::string> dirs = {fixture_dir("good"), fixture_dir("map_anchor")};
    {
        nlohmann::json cfg = nlohmann::json::parse(make_config(with_map));
        cfg["map"] = {{"path", "/does/not/exist.geojson"}};
        Engine e(cfg.dump(), dirs);
        CHECK(e.status() == PN_E_IO);
        CHECK(std::string(e.error().where) == "/map/path");
        CHECK(contains(e.error().message, "/does/not/exist.geojson"));
    }
    {
        nlohmann::json cfg = nlohmann::json::parse(make_config(kPipeline));
        cfg["map"] = {{"path", "/does/not/matter.geojson"}};
        Engine e(cfg.dump(), {fixture_dir("good")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK(std::string(e.error().where) == "/map");
    }
    const std::string path = "app_settings_test_map.geojson";
    {
        std::ofstream out(path);
        out << R"({"type": "FeatureCollection", "pednav:origin": [11.5, 48.1, 500],
                   "features": [{"type": "Feature", "geometry": {"type": "Point", "coordinates": [11.5, 48.1]}},
                                {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": []}}]})";
    }
    {
        nlohmann::json cfg = nlohmann::json::parse(make_config(with_map));
        cfg["map"] = {{"path", path}};
        Engine e(cfg.dump(), dirs);
        CHECK(e.status() == PN_E_BAD_INPUT);
        CHECK(std::string(e.error().where) == "map:/features/1/geometry/type");
        CHECK(contains(e.error().message, path + ": foot/map_matcher refused the pednav.map/1 map"));
    }
    {
        std::ofstream out(path);
        out << R"({"type": "FeatureCollection", "pednav:origin": [11.5, 48.1, 500],
                   "features": [{"type": "Feature", "geometry": {"type": "Point", "coordinates": [11.5, 48.1]}}]})";
    }
    nlohmann::json cfg = nlohmann::json::parse(make_config(with_map));
    cfg["map"] = {{"path", path}, {"format", "pednav.map/1"}};
    Engine e(cfg.dump(), dirs);
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    const auto d = e.describe();
    CHECK(d["map"]["from"] == path);
    CHECK(d["origin"]["from"] == "a plugin");
    CHECK(d["origin"]["given_by"] == "foot/map_matcher");
    CHECK(d["origin"]["lat_deg"] == 48.1);
    std::remove(path.c_str());
}

TEST_CASE("an origin in the config is the engine's; the app cannot replace it") {
    nlohmann::json cfg = nlohmann::json::parse(make_config(kPipeline));
    cfg["origin"] = {{"lat_deg", -33.9}, {"lon_deg", 151.2}, {"height_m", 20.0}};
    Engine e(cfg.dump(), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_geo_point_t o;
    REQUIRE(pn_engine_get_origin(e.get(), &o) == PN_OK);
    CHECK(o.lat_deg == -33.9);
    CHECK(o.height_m == 20.0);
    pn_error_t err = make_error();
    const pn_geo_point_t other{1.0, 2.0, 3.0};
    CHECK(pn_engine_set_origin(e.get(), &other, &err) == PN_E_BAD_STATE);
    CHECK(contains(err.message, "from the config"));
    const pn_geo_point_t bad{91.0, 0.0, 0.0};
    CHECK(pn_engine_set_origin(e.get(), &bad, &err) == PN_E_INVALID_ARGUMENT);
    double enu[3];
    const pn_geo_point_t p{-33.9, 151.2, 20.0};
    REQUIRE(pn_engine_enu_from_geo(e.get(), &p, enu) == PN_OK);
    CHECK(std::fabs(enu[0]) + std::fabs(enu[1]) + std::fabs(enu[2]) < 1e-6);
}

TEST_CASE("origin and map keys of the config are checked") {
    auto refused = [](const nlohmann::json& extra, const std::string& where) {
        nlohmann::json cfg = nlohmann::json::parse(make_config(kPipeline));
        cfg.update(extra);
        Engine e(cfg.dump(), {fixture_dir("good")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK(std::string(e.error().where) == where);
    };
    refused({{"origin", {{"lat_deg", 10.0}}}}, "/origin/lon_deg");
    refused({{"origin", {{"lat_deg", 100.0}, {"lon_deg", 0.0}}}}, "/origin/lat_deg");
    refused({{"origin", {{"lat", 1.0}}}}, "/origin/lat");
    refused({{"origin", {{"from_fix_max_h_accuracy_m", -1.0}}}}, "/origin/from_fix_max_h_accuracy_m");
    refused({{"map", {{"format", "pednav.map/1"}}}}, "/map/path");
    refused({{"map", "building.geojson"}}, "/map");
}

TEST_CASE("an output queue larger than PN_OUTPUT_QUEUE_MAX is refused") {
    Engine e(make_config(kPipeline), {fixture_dir("good")}, PN_OUTPUT_QUEUE_MAX + 1);
    CHECK(e.status() == PN_E_INVALID_ARGUMENT);
    CHECK(contains(e.error().message, "PN_OUTPUT_QUEUE_MAX"));
}

TEST_CASE("reconfigure checks the new params against the plugin's schema, as the config") {
    Engine e(make_config({{"step_detector", "org.pednav.test.schema_steps"}}), {fixture_dir("schema")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    CHECK(pn_engine_reconfigure(e.get(), "step_detector", R"({"every_n": 5000})", 0, &err) == PN_E_INVALID_CONFIG);
    CHECK(std::string(err.where) == "/params/every_n");
    CHECK_MESSAGE(contains(err.message, "every_n is 5000, outside [1, 1000]"), err.message);
    CHECK(pn_engine_reconfigure(e.get(), "step_detector", R"({"gain": "high"})", 0, &err) == PN_E_INVALID_CONFIG);
    CHECK(std::string(err.where) == "/params/gain");
    CHECK(pn_engine_reconfigure(e.get(), "step_detector", "[1]", 0, &err) == PN_E_INVALID_CONFIG);
    CHECK(std::string(err.where) == "/params");
    // In range: taken, and the gait phases carry the new gain from the next sample on.
    REQUIRE(push(e, walk(0, 5)) == PN_OK);
    REQUIRE(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_GAIT_PHASE)) == PN_OK);
    REQUIRE(pn_engine_reconfigure(e.get(), "step_detector", R"({"gain": 1.5, "sign": "negative"})", 0, &err) == PN_OK);
    REQUIRE(push(e, walk(5, 5)) == PN_OK);
    const auto g = of_type(e.poll_all(), PN_REC_GAIT_PHASE);
    REQUIRE(g.size() == 5);  // samples 4..8: 4 was processed after the change (it waited for sample 5)
    for (const auto& o : g) CHECK(o.gait_phase.statistic == -1.5);
}
