// SPDX-License-Identifier: Apache-2.0
// A preset with a merge patch: values merged, a replaced plugin's params reset, bad input named.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <pednav_eval/config_patch.hpp>

using pednav::eval::patched_config;

namespace {
const std::string kPreset = R"({"format": "pednav-config/1", "mount": "foot", "pipelines": {"foot": {
    "step_detector": {"plugin": "org.pednav.foot.stance.shoe", "params": {"threshold": 0.5, "window_s": 0.06}},
    "position_filter": {"plugin": "org.pednav.foot.ekf15", "params": {"zupt": true, "hupt": true}}}}})";
}

TEST_CASE("patched_config: the patch's values replace the preset's, the rest stays") {
    const auto doc = nlohmann::json::parse(
        patched_config(kPreset, {{"pipelines", {{"foot", {{"position_filter", {{"params", {{"hupt", false}}}}}}}}}}));
    const auto& filter = doc["pipelines"]["foot"]["position_filter"];
    CHECK(filter["plugin"] == "org.pednav.foot.ekf15");
    CHECK(filter["params"]["hupt"] == false);
    CHECK(filter["params"]["zupt"] == true);
    CHECK(doc["pipelines"]["foot"]["step_detector"]["params"]["threshold"] == 0.5);
    // An empty patch gives the preset back.
    CHECK(nlohmann::json::parse(patched_config(kPreset, nlohmann::json::object())) == nlohmann::json::parse(kPreset));
}

TEST_CASE("patched_config: a stage whose plugin is replaced starts from the new plugin's defaults") {
    nlohmann::json patch;
    patch["pipelines"]["foot"]["step_detector"] = {{"plugin", "org.pednav.foot.stance.multicondition"},
                                                   {"params", {{"window_s", 0.2}}}};
    const auto doc = nlohmann::json::parse(patched_config(kPreset, patch));
    const auto& det = doc["pipelines"]["foot"]["step_detector"];
    CHECK(det["plugin"] == "org.pednav.foot.stance.multicondition");
    CHECK(det["params"] == nlohmann::json{{"window_s", 0.2}});  // SHOE's threshold is gone
    // Naming the preset's own plugin keeps its params.
    nlohmann::json same;
    same["pipelines"]["foot"]["position_filter"]["plugin"] = "org.pednav.foot.ekf15";
    CHECK(nlohmann::json::parse(patched_config(kPreset, same))["pipelines"]["foot"]["position_filter"]["params"]
              .size() == 2);
}

TEST_CASE("patched_config: a preset that is not JSON or a patch that is not an object is refused") {
    CHECK_THROWS_WITH_AS(patched_config("{\"format\": ", nlohmann::json::object()), doctest::Contains("preset: "),
                         std::runtime_error);
    CHECK_THROWS_WITH_AS(patched_config(kPreset, nlohmann::json::array({1})),
                         doctest::Contains("expected a JSON object, got [1]"), std::runtime_error);
}
