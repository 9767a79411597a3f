// SPDX-License-Identifier: Apache-2.0
// "params": bad values derived from the plugin's params schema must be
// refused at create, naming the key.
#include <cmath>

#include <pednav_sdk/params_schema.hpp>

#include "checks.hpp"
#include "engine_run.hpp"

namespace pednav::validate {

namespace {

struct BadValue {
    std::string key;
    nlohmann::json value;
    std::string what;  // "wrong type", "above the maximum", ...
};

// A value just past a bound, by at least 1 (and integral for an integer).
double past(double bound, double direction, bool integer) {
    const double v = bound + direction * std::max(1.0, std::fabs(bound));
    return integer ? (direction > 0 ? std::ceil(v) : std::floor(v)) : v;
}

std::vector<BadValue> bad_values(const sdk::ParamsSchema& schema) {
    std::vector<BadValue> out;
    for (const auto& p : schema.params()) {
        using sdk::ParamType;
        const bool integer = p.type == ParamType::integer;
        switch (p.type) {
            case ParamType::number:
            case ParamType::integer:
                out.push_back({p.key, "not a number", "wrong type (string for a number)"});
                if (integer) out.push_back({p.key, 0.5, "not an integer"});
                if (p.has_maximum) out.push_back({p.key, past(p.maximum, +1, integer), "above the maximum"});
                if (p.has_minimum) out.push_back({p.key, past(p.minimum, -1, integer), "below the minimum"});
                break;
            case ParamType::boolean: out.push_back({p.key, 2, "wrong type (number for a boolean)"}); break;
            case ParamType::string:
                out.push_back({p.key, 3, "wrong type (number for a string)"});
                if (!p.allowed.empty()) out.push_back({p.key, "no-such-choice", "not one of the enum"});
                break;
        }
    }
    return out;
}

}  // namespace

nlohmann::json params_check(const Placement& p) {
    nlohmann::json detail = {{"tried", 0}};
    const std::string params_pointer = p.pointer() + "/params";
    auto with_params = [&](const nlohmann::json& params) {
        nlohmann::json config = p.config;
        config["pipelines"][p.mount][p.role]["params"] = params;
        return config;
    };
    {
        EngineRun defaults(with_params(nlohmann::json::object()), p.plugin_dirs);
        if (!defaults.created())
            return check_result(false, "the defaults alone are refused: " + defaults.error_text(), detail);
    }
    std::vector<BadValue> cases = {{"no_such_parameter", 1, "unknown key"}};
    if (p.params_schema.is_object()) {
        try {
            for (auto& b : bad_values(sdk::ParamsSchema::from_json(p.params_schema))) cases.push_back(std::move(b));
        } catch (const sdk::SchemaError& e) {
            return check_result(false, std::string("the params schema is unusable: ") + e.what(), detail);
        }
    } else {
        detail["note"] = "no params schema: only an unknown key is tried";
    }
    // Each bad value alone, on top of the preset's params.
    const nlohmann::json base = p.config["pipelines"][p.mount][p.role].value("params", nlohmann::json::object());
    for (const auto& c : cases) {
        nlohmann::json params = base;
        params[c.key] = c.value;
        EngineRun e(with_params(params), p.plugin_dirs);
        const std::string case_text = c.key + " = " + c.value.dump() + " (" + c.what + ")";
        if (e.created()) return check_result(false, "accepted " + case_text, detail);
        const std::string expected_where = params_pointer + "/" + c.key;
        if (e.error().code != PN_E_INVALID_CONFIG)
            return check_result(false, "refused " + case_text + " with " + e.error_text() + ", not PN_E_INVALID_CONFIG",
                                detail);
        if (expected_where != e.error().where)
            return check_result(false, "refused " + case_text + " naming \"" + e.error().where + "\", not \"" +
                                           expected_where + "\"",
                                detail);
        detail["tried"] = detail["tried"].get<int>() + 1;
    }
    return check_result(true, "", detail);
}

}  // namespace pednav::validate
