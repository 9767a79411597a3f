// SPDX-License-Identifier: Apache-2.0
#include "params_schema.hpp"

#include <algorithm>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav_sdk/params_schema.hpp>

#include "parsed_text_cache.hpp"

namespace pednav::engine {

namespace {

// A key as one JSON pointer token (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string pointer_token(const std::string& key) {
    std::string t;
    for (char c : key) {
        if (c == '~')
            t += "~0";
        else if (c == '/')
            t += "~1";
        else
            t += c;
    }
    return t;
}

// Levenshtein distance between two keys.
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

// " (did you mean \"window_s\"?)" for a near miss, else where the keys are listed.
std::string hint_for(const std::string& key, const sdk::ParamsSchema& schema) {
    const sdk::ParamSpec* best = nullptr;
    size_t best_distance = std::max<size_t>(2, key.size() / 3) + 1;
    for (const auto& p : schema.params()) {
        const size_t d = edit_distance(key, p.key);
        if (d < best_distance) {
            best = &p;
            best_distance = d;
        }
    }
    return best ? " (did you mean \"" + best->key + "\"?)" : " (pednav plugins --params lists them)";
}

// Each plugin's schema is parsed once per process (parsed_text_cache.hpp).
std::shared_ptr<const sdk::ParamsSchema> parsed_schema(const char* schema_json) {
    static ParsedTextCache<sdk::ParamsSchema> schemas;
    return schemas.get(schema_json, [](const std::string& text) { return sdk::ParamsSchema::parse(text); });
}

}  // namespace

void check_params_against_schema(const pnp_descriptor_t& plugin, const StageConfig& stage) {
    if (!plugin.params_schema_json) return;
    const std::string id = plugin.id;
    std::shared_ptr<const sdk::ParamsSchema> parsed;
    try {
        parsed = parsed_schema(plugin.params_schema_json);
    } catch (const sdk::SchemaError& e) {
        throw ConfigProblem{PN_E_INTERNAL, stage.pointer + "/plugin",
                            "plugin " + id + " cannot be configured: its " + e.what()};
    }
    const sdk::ParamsSchema& schema = *parsed;
    // parse_config re-serialised params from a JSON object: this parse holds.
    const nlohmann::json params = nlohmann::json::parse(stage.params_json);
    const std::string base = stage.pointer + "/params/";
    for (auto it = params.begin(); it != params.end(); ++it) {
        const sdk::ParamSpec* spec = schema.find(it.key());
        if (!spec)
            throw ConfigProblem{PN_E_INVALID_CONFIG, base + pointer_token(it.key()),
                                id + ": unknown parameter \"" + it.key() + "\"" + hint_for(it.key(), schema)};
        if (it->is_null()) continue;
        const std::string problem = sdk::param_problem(*spec, *it);
        if (!problem.empty())
            throw ConfigProblem{PN_E_INVALID_CONFIG, base + pointer_token(it.key()), id + ": " + problem};
    }
}

}  // namespace pednav::engine
