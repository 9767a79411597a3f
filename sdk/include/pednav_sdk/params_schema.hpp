// SPDX-License-Identifier: Apache-2.0
// A plugin's parameter schema: the JSON Schema subset that
// pnp_descriptor_t::params_schema_json may use, parsed and checked. The SDK's
// Params takes defaults and ranges from it, the engine checks configs against
// it before create, and `pednav plugins --params` prints it.
//
// The subset (docs/parameters.md):
//   {"type": "object", "additionalProperties": false,
//    "properties": {"<key>": {"type": "number" | "integer" | "boolean" | "string",
//                             "default": <value>, "description": "<meaning>",
//                             "minimum": <n>, "maximum": <n>,   (number, integer)
//                             "x-unit": "<unit>",               (number, integer)
//                             "enum": ["<a>", ...]}}}           (string)
// plus "$schema", "title" and "description" at the top. Every property has a
// type, a default and a description; "additionalProperties" is false (an
// unknown key is refused). Any other keyword makes the schema unusable.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pednav::sdk {

// A mistake in the plugin, not in the config: a schema outside the subset, or
// code reading a parameter its schema does not declare.
class SchemaError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

enum class ParamType { number, integer, boolean, string };

inline const char* param_type_name(ParamType t) {
    switch (t) {
        case ParamType::number: return "number";
        case ParamType::integer: return "integer";
        case ParamType::boolean: return "boolean";
        case ParamType::string: return "string";
    }
    return "?";
}

// One declared parameter.
struct ParamSpec {
    std::string key;
    ParamType type = ParamType::number;
    std::string unit;  // "x-unit"; empty when not given
    bool has_minimum = false, has_maximum = false;
    double minimum = -HUGE_VAL, maximum = HUGE_VAL;
    nlohmann::json default_value;
    std::string description;
    std::vector<std::string> allowed;  // "enum" of a string; empty = any string
};

// The shortest text that reads back as the same double: "0.06", "200",
// "9.80665"; exponents only below 1e-4 and from 1e6 on ("1e-05", "1e+06").
inline std::string format_number(double x) {
    const double magnitude = std::fabs(x);
    // %g switches to an exponent when the exponent reaches the precision:
    // in the fixed range, keep at least as many digits as the integer part has.
    int min_precision = 1;
    if (magnitude >= 1.0 && magnitude < 1e6)
        min_precision = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    char buf[40];
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", std::max(precision, min_precision), x);
        if (std::strtod(buf, nullptr) == x) break;
    }
    return buf;
}

// A value as the tables and messages show it: numbers shortest, strings bare.
inline std::string format_value(const nlohmann::json& v) {
    if (v.is_number()) return format_number(v.get<double>());
    if (v.is_string()) return v.get<std::string>();
    return v.dump();
}

// "[0, 2]", ">= 0", "<= 2", "one of a, b" or "" (anything of the type).
inline std::string range_text(const ParamSpec& p) {
    if (!p.allowed.empty()) {
        std::string s = "one of ";
        for (size_t i = 0; i < p.allowed.size(); ++i) s += (i ? ", " : "") + p.allowed[i];
        return s;
    }
    if (p.has_minimum && p.has_maximum)
        return "[" + format_number(p.minimum) + ", " + format_number(p.maximum) + "]";
    if (p.has_minimum) return ">= " + format_number(p.minimum);
    if (p.has_maximum) return "<= " + format_number(p.maximum);
    return "";
}

// Why `value` is not acceptable for `p`, as a sentence naming the key
// ("window_s is 5, outside [0, 2] s"); empty when it is acceptable.
inline std::string param_problem(const ParamSpec& p, const nlohmann::json& value) {
    const std::string unit = p.unit.empty() ? "" : " " + p.unit;
    const std::string shown =
        value.is_string() ? "\"" + value.get<std::string>() + "\"" : format_value(value);
    switch (p.type) {
        case ParamType::boolean:
            return value.is_boolean() ? "" : p.key + " must be true or false, not " + shown;
        case ParamType::string: {
            if (!value.is_string()) return p.key + " must be a string, not " + shown;
            if (p.allowed.empty()) return "";
            for (const auto& a : p.allowed)
                if (a == value.get<std::string>()) return "";
            return p.key + " is " + shown + ", not " + range_text(p);
        }
        case ParamType::number:
        case ParamType::integer: {
            if (!value.is_number()) return p.key + " must be a number, not " + shown;
            const double x = value.get<double>();
            // An integer is a number without a fraction (3 or 3.0), within the
            // range a double holds exactly (2^53).
            if (p.type == ParamType::integer && !(x == std::floor(x) && std::fabs(x) <= 9007199254740992.0))
                return p.key + " must be an integer, not " + shown;
            if ((p.has_minimum && x < p.minimum) || (p.has_maximum && x > p.maximum)) {
                if (p.has_minimum && p.has_maximum)
                    return p.key + " is " + shown + ", outside " + range_text(p) + unit;
                if (p.has_minimum)
                    return p.key + " is " + shown + ", below the minimum " + format_number(p.minimum) + unit;
                return p.key + " is " + shown + ", above the maximum " + format_number(p.maximum) + unit;
            }
            return "";
        }
    }
    return "";
}

class ParamsSchema {
public:
    // Parses a schema document. Throws SchemaError; its message starts with
    // "params schema" and the catcher names the plugin.
    static ParamsSchema parse(const std::string& schema_json) {
        nlohmann::json doc;
        try {
            doc = nlohmann::json::parse(schema_json);
        } catch (const nlohmann::json::exception& e) {
            throw SchemaError(std::string("params schema is not valid JSON: ") + e.what());
        }
        return from_json(doc);
    }

    // Checks a parsed schema document against the subset. Throws SchemaError.
    static ParamsSchema from_json(const nlohmann::json& doc) {
        const std::string at = "params schema ";
        if (!doc.is_object()) throw SchemaError(at + "must be a JSON object");
        only(doc, {"$schema", "title", "description", "type", "properties", "additionalProperties"}, at);
        for (const char* k : {"$schema", "title", "description"})
            if (doc.contains(k) && !doc.at(k).is_string())
                throw SchemaError(at + "\"" + k + "\" must be a string");
        if (doc.value("type", nlohmann::json()) != "object")
            throw SchemaError(at + "needs \"type\": \"object\"");
        if (doc.value("additionalProperties", nlohmann::json()) != false)
            throw SchemaError(at + "needs \"additionalProperties\": false (unknown keys are refused)");
        auto props = doc.find("properties");
        if (props == doc.end() || !props->is_object())
            throw SchemaError(at + "needs a \"properties\" object");
        ParamsSchema s;
        for (auto it = props->begin(); it != props->end(); ++it)
            s.params_.push_back(property(it.key(), *it, at));
        return s;
    }

    // Declared parameters, sorted by key.
    const std::vector<ParamSpec>& params() const { return params_; }
    const ParamSpec* find(const std::string& key) const {
        for (const auto& p : params_)
            if (p.key == key) return &p;
        return nullptr;
    }

private:
    static void only(const nlohmann::json& obj, std::initializer_list<const char*> allowed,
                     const std::string& at) {
        for (auto it = obj.begin(); it != obj.end(); ++it) {
            bool ok = false;
            std::string list;
            for (const char* a : allowed) {
                ok = ok || it.key() == a;
                list += (list.empty() ? "" : ", ") + std::string(a);
            }
            if (!ok)
                throw SchemaError(at + "uses keyword \"" + it.key() + "\", outside the supported subset (" +
                                  list + "; docs/parameters.md)");
        }
    }

    static ParamSpec property(const std::string& key, const nlohmann::json& j, const std::string& owner_at) {
        const std::string at = owner_at + "property \"" + key + "\" ";
        if (key.empty()) throw SchemaError(owner_at + "declares a property with an empty name");
        if (!j.is_object()) throw SchemaError(at + "must be an object");
        only(j, {"type", "default", "description", "minimum", "maximum", "x-unit", "enum"}, at);
        ParamSpec p;
        p.key = key;
        auto t = j.find("type");
        const std::string type = t != j.end() && t->is_string() ? t->get<std::string>() : "";
        if (type == "number")
            p.type = ParamType::number;
        else if (type == "integer")
            p.type = ParamType::integer;
        else if (type == "boolean")
            p.type = ParamType::boolean;
        else if (type == "string")
            p.type = ParamType::string;
        else
            throw SchemaError(at + "needs \"type\": number, integer, boolean or string");
        const bool numeric = p.type == ParamType::number || p.type == ParamType::integer;
        for (const char* k : {"minimum", "maximum"}) {
            if (!j.contains(k)) continue;
            if (!numeric)
                throw SchemaError(at + "has \"" + k + "\", which only a number or an integer takes");
            if (!j.at(k).is_number()) throw SchemaError(at + "\"" + k + "\" must be a number");
        }
        if (j.contains("minimum")) {
            p.has_minimum = true;
            p.minimum = j.at("minimum").get<double>();
        }
        if (j.contains("maximum")) {
            p.has_maximum = true;
            p.maximum = j.at("maximum").get<double>();
        }
        if (p.has_minimum && p.has_maximum && p.minimum > p.maximum)
            throw SchemaError(at + "has \"minimum\" above \"maximum\"");
        if (j.contains("x-unit")) {
            if (!numeric) throw SchemaError(at + "has \"x-unit\", which only a number or an integer takes");
            if (!j.at("x-unit").is_string()) throw SchemaError(at + "\"x-unit\" must be a string");
            p.unit = j.at("x-unit").get<std::string>();
        }
        if (j.contains("enum")) {
            const auto& e = j.at("enum");
            if (p.type != ParamType::string)
                throw SchemaError(at + "has \"enum\", which only a string takes");
            if (!e.is_array() || e.empty())
                throw SchemaError(at + "\"enum\" must be a non-empty array of strings");
            for (const auto& v : e) {
                if (!v.is_string()) throw SchemaError(at + "\"enum\" must be a non-empty array of strings");
                p.allowed.push_back(v.get<std::string>());
            }
        }
        auto d = j.find("description");
        if (d == j.end() || !d->is_string() || d->get<std::string>().empty())
            throw SchemaError(at + "needs a \"description\" (its meaning)");
        p.description = d->get<std::string>();
        auto def = j.find("default");
        if (def == j.end()) throw SchemaError(at + "needs a \"default\"");
        const std::string problem = param_problem(p, *def);
        if (!problem.empty()) throw SchemaError(at + "has a default the schema itself refuses: " + problem);
        p.default_value = *def;
        return p;
    }

    std::vector<ParamSpec> params_;
};

}  // namespace pednav::sdk
