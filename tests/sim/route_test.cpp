// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include <pednav_sim/route.hpp>

using namespace pednav::sim;
using nlohmann::json;

namespace {

std::string error_of(const json& j) {
    try {
        parse_route(j);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("route: built-in routes exist, round-trip through JSON, and have the documented lengths") {
    CHECK(builtin_route_names().size() == 6);
    for (const std::string& name : builtin_route_names()) {
        CAPTURE(name);
        const Route r = builtin_route(name);
        CHECK(r.name == name);
        const Route back = parse_route(route_to_json(r));
        CHECK(route_to_json(back) == route_to_json(r));
    }
    CHECK(route_length_m(builtin_route("corridor_loop")) == doctest::Approx(120.0));
    CHECK(route_length_m(builtin_route("stairs")) ==
          doctest::Approx(2 * (10 + 2.8 + 1.5 + 2.8) + 10 + 1.5 + 10 + 1.5));
    CHECK_THROWS_AS(builtin_route("nowhere"), std::runtime_error);
}

TEST_CASE("route: parsing fills defaults, infers stairs, and names the bad key") {
    const Route r = parse_route(
        json::parse(R"({"waypoints": [[0,0,0], [10,0,0], {"enu_m": [12.8,0,1.7], "outdoor": true}]})"));
    REQUIRE(r.waypoints.size() == 3);
    CHECK_FALSE(r.waypoints[1].stairs);
    CHECK(r.waypoints[2].stairs);
    CHECK(r.waypoints[2].outdoor);
    CHECK(r.speed_mps == 1.3);

    CHECK(error_of(json::parse(R"({"waypoints": [[0,0,0]]})")).find("/waypoints") != std::string::npos);
    CHECK(error_of(json::parse(R"({"waypoints": [[0,0,0],[1,0,0]], "sped_mps": 1})")).find("/sped_mps") !=
          std::string::npos);
    CHECK(error_of(json::parse(R"({"waypoints": [[0,0,0],{"enu_m":[1,0]}]})")).find("/waypoints/1/enu_m") !=
          std::string::npos);
    CHECK(error_of(json::parse(R"({"waypoints": [[0,0,0],[1,0,0]], "speed_mps": 9})")).find("/speed_mps") !=
          std::string::npos);
    CHECK(error_of(json::parse(R"({"waypoints": [[0,0,0],{"enu_m":[1,0,1], "stairs": false}]})"))
              .find("/waypoints/1/stairs") != std::string::npos);
    CHECK(error_of(json::parse(R"({"waypoints": [[0,0,0],[1,0,0]], "walls": [{"points_enu_m": [[0,0]]}]})"))
              .find("/walls/0/points_enu_m") != std::string::npos);
}
