// SPDX-License-Identifier: Apache-2.0
#include <pednav_eval/config_patch.hpp>

#include <stdexcept>

namespace pednav::eval {

std::string patched_config(const std::string& preset_json, const nlohmann::json& patch) {
    if (!patch.is_object()) throw std::runtime_error("config patch: expected a JSON object, got " + patch.dump());
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(preset_json);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(std::string("preset: ") + e.what());
    }
    const auto pipelines = patch.find("pipelines");
    if (pipelines != patch.end() && pipelines->is_object() && doc.contains("pipelines")) {
        for (const auto& [pipeline, stages] : pipelines->items()) {
            if (!stages.is_object() || !doc["pipelines"].contains(pipeline)) continue;
            nlohmann::json& preset_stages = doc["pipelines"][pipeline];
            for (const auto& [stage, settings] : stages.items()) {
                if (!settings.is_object() || !settings.contains("plugin") || !settings["plugin"].is_string() ||
                    !preset_stages.contains(stage))
                    continue;
                nlohmann::json& preset_stage = preset_stages[stage];
                if (preset_stage.is_object() && preset_stage.value("plugin", nlohmann::json()) != settings["plugin"])
                    preset_stage["params"] = nlohmann::json::object();
            }
        }
    }
    doc.merge_patch(patch);
    return doc.dump();
}

std::string with_user_height(const std::string& config_json, double height_m) {
    if (!(height_m > 0)) return config_json;
    nlohmann::json doc = nlohmann::json::parse(config_json);
    if (doc.contains("pipelines") && doc["pipelines"].is_object())
        for (auto& [name, stages] : doc["pipelines"].items()) {
            if (!stages.is_object() || !stages.contains("position_filter")) continue;
            nlohmann::json& filter = stages["position_filter"];
            if (filter.is_object() && filter.contains("params") && filter["params"].is_object() &&
                filter["params"].contains("user_height_m"))
                filter["params"]["user_height_m"] = height_m;
        }
    return doc.dump();
}

}  // namespace pednav::eval
