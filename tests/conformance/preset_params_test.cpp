// SPDX-License-Identifier: Apache-2.0
// The presets (configs/*.json) agree with the parameter schemas of the
// first-party plugins they name: each stage lists every parameter of its
// plugin, at the schema's default, and nothing else. A changed default thus
// fails here until the preset is changed with it (docs/parameters.md).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav_sdk/params_schema.hpp>

#include "test_support.hpp"

namespace {

using nlohmann::json;

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> preset_paths() {
    std::vector<std::string> paths;
    for (const auto& e : std::filesystem::directory_iterator(PEDNAV_CONFIG_DIR))
        if (e.path().extension() == ".json") paths.push_back(e.path().string());
    std::sort(paths.begin(), paths.end());
    return paths;
}

// The plugin entries of the describe output of an engine on `preset`, or the
// engine's error.
json described_plugins(const std::string& preset, std::string& error) {
    const pednav::test::Engine e(preset, {PEDNAV_PLUGIN_OUTPUT_DIR});
    if (!e.get()) {
        error = std::string(e.error().where) + ": " + e.error().message;
        return json::array();
    }
    return e.describe().at("plugins");
}

bool same_value(const json& a, const json& b) {
    if (a.is_number() && b.is_number()) return a.get<double>() == b.get<double>();
    return a == b;
}

// Every way the preset `name` disagrees with the schemas, one sentence each.
std::vector<std::string> preset_disagreements(const std::string& name, const json& preset,
                                              const json& plugins) {
    std::vector<std::string> out;
    for (const auto& [mount, pipeline] : preset.at("pipelines").items()) {
        for (const auto& [role, stage] : pipeline.items()) {
            const std::string at = name + ": /pipelines/" + mount + "/" + role + "/params";
            const std::string id = stage.at("plugin").get<std::string>();
            const json* schema_json = nullptr;
            for (const auto& p : plugins)
                if (p.at("id") == id) schema_json = &p.at("params_schema");
            if (!schema_json || schema_json->is_null()) {
                out.push_back(at + ": plugin " + id +
                              (schema_json ? " has no params schema" : " was not loaded"));
                continue;
            }
            const auto schema = pednav::sdk::ParamsSchema::from_json(*schema_json);
            const json params = stage.value("params", json::object());
            for (const auto& [key, value] : params.items())
                if (!schema.find(key)) out.push_back(at + "/" + key + ": not a parameter of " + id);
            for (const auto& spec : schema.params()) {
                const std::string def = pednav::sdk::format_value(spec.default_value);
                auto it = params.find(spec.key);
                if (it == params.end())
                    out.push_back(at + "/" + spec.key + ": missing (a preset lists every parameter; " + id +
                                  "'s default is " + def + ")");
                else if (!same_value(*it, spec.default_value))
                    out.push_back(at + "/" + spec.key + " is " + pednav::sdk::format_value(*it) + ", " + id +
                                  "'s schema default is " + def);
            }
        }
    }
    return out;
}

}  // namespace

TEST_CASE("every preset lists every parameter of its plugins at the schema default") {
    const auto paths = preset_paths();
    INFO("presets in " << PEDNAV_CONFIG_DIR);
    REQUIRE(!paths.empty());
    for (const auto& path : paths) {
        CAPTURE(path);
        const std::string text = read_file(path);
        std::string error;
        const json plugins = described_plugins(text, error);
        INFO(error);
        REQUIRE(error.empty());
        const auto found =
            preset_disagreements(std::filesystem::path(path).filename().string(), json::parse(text), plugins);
        for (const auto& d : found) MESSAGE(d);
        if (!found.empty())
            MESSAGE(
                "set the preset's values to the schema defaults, or change the default in the plugin's "
                "schema "
                "(docs/parameters.md)");
        CHECK(found.empty());
    }
}

TEST_CASE("a preset that disagrees with a schema is named: value, unknown key, missing key") {
    const std::string text = read_file(std::string(PEDNAV_CONFIG_DIR) + "/foot.json");
    REQUIRE(!text.empty());
    std::string error;
    const json plugins = described_plugins(text, error);
    REQUIRE(error.empty());
    json preset = json::parse(text);
    REQUIRE(preset_disagreements("foot.json", preset, plugins).empty());
    // The preset's values are the defaults; the expected messages are made from them.
    using pednav::sdk::format_number;
    json& ekf = preset["pipelines"]["foot"]["position_filter"]["params"];
    const double swing_default_s = ekf.at("swing_propagation_s").get<double>();
    ekf["swing_propagation_s"] = swing_default_s + 0.25;
    ekf["swing_propagation"] = 0.1;
    json& detector = preset["pipelines"]["foot"]["step_detector"]["params"];
    const double window_default_s = detector.at("window_s").get<double>();
    detector.erase("window_s");
    const auto found = preset_disagreements("foot.json", preset, plugins);
    REQUIRE(found.size() == 3);
    CHECK(found[0] ==
          "foot.json: /pipelines/foot/position_filter/params/swing_propagation: not a parameter of "
          "org.pednav.foot.ekf15");
    CHECK(found[1] == "foot.json: /pipelines/foot/position_filter/params/swing_propagation_s is " +
                          format_number(swing_default_s + 0.25) +
                          ", org.pednav.foot.ekf15's schema default is " + format_number(swing_default_s));
    CHECK(found[2] ==
          "foot.json: /pipelines/foot/step_detector/params/window_s: missing (a preset lists every "
          "parameter; org.pednav.foot.stance.shoe's default is " +
              format_number(window_default_s) + ")");
}

TEST_CASE("every first-party plugin declares a params schema in the subset") {
    const std::string text = read_file(std::string(PEDNAV_CONFIG_DIR) + "/foot.json");
    std::string error;
    const json plugins = described_plugins(text, error);
    REQUIRE(error.empty());
    REQUIRE(plugins.size() >= 5);
    for (const auto& p : plugins) {
        CAPTURE(p.at("id").get<std::string>());
        REQUIRE(p.at("params_schema").is_object());
        const auto schema = pednav::sdk::ParamsSchema::from_json(p.at("params_schema"));
        CHECK(!schema.params().empty());
        for (const auto& spec : schema.params()) {
            CAPTURE(spec.key);
            // First-party numbers have a closed range, which the tables show.
            if (spec.type == pednav::sdk::ParamType::number) CHECK((spec.has_minimum && spec.has_maximum));
        }
    }
}
