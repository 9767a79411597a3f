// SPDX-License-Identifier: Apache-2.0
// Strict, typed access to a plugin's "params" object.
//
// With a params schema (the plugin's kParamsSchema, params_schema.hpp), the
// getters take only the key: p.number("window_s") returns the config's value
// or the schema's default, checked against the schema's type and range.
// Reading a key the schema does not declare, or leaving a declared one unread,
// is a SchemaError (a mistake in the plugin, reported at create). Without a
// schema, the getters take the default and range as arguments, as before.
//
// Every getter records the key as known; check_no_unknown_keys() then rejects
// any key the plugin never asked for, naming it, so a typo in a config is an
// error instead of a silently ignored setting. Errors throw ConfigError with
// the JSON pointer of the key ("/window_s"); the engine prefixes the pipeline
// path.
#pragma once

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "params_schema.hpp"

namespace pednav::sdk {

// A bad params value. where() is a JSON pointer relative to the params object.
class ConfigError : public std::runtime_error {
public:
    ConfigError(std::string where, const std::string& message)
        : std::runtime_error(message), where_(std::move(where)) {}
    const std::string& where() const { return where_; }

private:
    std::string where_;
};

class Params {
public:
    Params() : json_(nlohmann::json::object()) {}
    // `schema` (may be NULL: no schema) must outlive the Params.
    explicit Params(const std::string& text, const ParamsSchema* schema = nullptr) : schema_(schema) {
        if (text.empty()) {
            json_ = nlohmann::json::object();
            return;
        }
        try {
            json_ = nlohmann::json::parse(text);
        } catch (const nlohmann::json::exception& e) {
            throw ConfigError("", std::string("params are not valid JSON: ") + e.what());
        }
        if (json_.is_null()) json_ = nlohmann::json::object();
        if (!json_.is_object()) throw ConfigError("", "params must be a JSON object");
    }

    const ParamsSchema* schema() const { return schema_; }

    // Getters of a plugin with a schema: the value, or the schema's default.
    double number(const std::string& key) { return declared(key, ParamType::number).get<double>(); }
    long integer(const std::string& key) {
        const nlohmann::json& v = declared(key, ParamType::integer);
        return v.is_number_integer() ? v.get<long>() : static_cast<long>(v.get<double>());
    }
    bool boolean(const std::string& key) { return declared(key, ParamType::boolean).get<bool>(); }
    std::string text(const std::string& key) { return declared(key, ParamType::string).get<std::string>(); }

    // Getters of a plugin without a schema.
    // A finite number in [min, max]; `fallback` when the key is absent.
    double number(const std::string& key, double fallback,
                  double min = -HUGE_VAL, double max = HUGE_VAL) {
        undeclared(key, "number");
        const nlohmann::json* v = find(key);
        if (!v) return fallback;
        if (!v->is_number()) fail(key, "must be a number");
        const double x = v->get<double>();
        if (!std::isfinite(x)) fail(key, "must be finite");
        if (x < min || x > max)
            fail(key, "is " + num(x) + ", outside [" + num(min) + ", " + num(max) + "]");
        return x;
    }

    long integer(const std::string& key, long fallback, long min = -2147483647L,
                 long max = 2147483647L) {
        undeclared(key, "integer");
        const nlohmann::json* v = find(key);
        if (!v) return fallback;
        if (!v->is_number_integer()) fail(key, "must be an integer");
        const long x = v->get<long>();
        if (x < min || x > max)
            fail(key, "is " + std::to_string(x) + ", outside [" + std::to_string(min) + ", " +
                          std::to_string(max) + "]");
        return x;
    }

    bool boolean(const std::string& key, bool fallback) {
        undeclared(key, "boolean");
        const nlohmann::json* v = find(key);
        if (!v) return fallback;
        if (!v->is_boolean()) fail(key, "must be true or false");
        return v->get<bool>();
    }

    // A string, optionally one of `allowed`.
    std::string text(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& allowed = {}) {
        undeclared(key, "text");
        const nlohmann::json* v = find(key);
        if (!v) return fallback;
        if (!v->is_string()) fail(key, "must be a string");
        std::string s = v->get<std::string>();
        if (!allowed.empty()) {
            bool ok = false;
            std::string list;
            for (const auto& a : allowed) {
                ok = ok || a == s;
                list += (list.empty() ? "" : ", ") + a;
            }
            if (!ok) fail(key, "is \"" + s + "\", expected one of: " + list);
        }
        return s;
    }

    // An array of exactly `size` finite numbers (any size when size == 0).
    // Arrays are outside the schema subset: for plugins without a schema.
    std::vector<double> numbers(const std::string& key, const std::vector<double>& fallback,
                                size_t size = 0) {
        if (schema_)
            throw SchemaError("parameter \"" + key +
                              "\" is read as an array, which the params schema subset has not");
        const nlohmann::json* v = find(key);
        if (!v) return fallback;
        if (!v->is_array()) fail(key, "must be an array of numbers");
        if (size != 0 && v->size() != size)
            fail(key, "must have " + std::to_string(size) + " elements, has " +
                          std::to_string(v->size()));
        std::vector<double> out;
        for (size_t i = 0; i < v->size(); ++i) {
            const auto& e = (*v)[i];
            if (!e.is_number() || !std::isfinite(e.get<double>()))
                throw ConfigError("/" + key + "/" + std::to_string(i), "must be a finite number");
            out.push_back(e.get<double>());
        }
        return out;
    }

    bool has(const std::string& key) const { return json_.contains(key); }
    const nlohmann::json& json() const { return json_; }

    // Throws for the first key that no getter asked for.
    void check_no_unknown_keys() const {
        for (auto it = json_.begin(); it != json_.end(); ++it)
            if (!known_.count(it.key()))
                throw ConfigError("/" + it.key(), "unknown parameter \"" + it.key() + "\"");
    }

    // With a schema: throws SchemaError for the first declared parameter no
    // getter read (the plugin's behaviour must follow every key it declares).
    void check_every_declared_read() const {
        if (!schema_) return;
        for (const auto& p : schema_->params())
            if (!known_.count(p.key))
                throw SchemaError("parameter \"" + p.key +
                                  "\" is declared in the params schema but the plugin never reads it");
    }

    [[noreturn]] static void fail(const std::string& key, const std::string& what) {
        throw ConfigError("/" + key, "parameter \"" + key + "\" " + what);
    }

private:
    // The value of a declared key, or its default; throws SchemaError for a
    // key the schema lacks or of another type, ConfigError for a bad value.
    const nlohmann::json& declared(const std::string& key, ParamType type) {
        if (!schema_)
            throw SchemaError("parameter \"" + key +
                              "\" is read without a default, but the plugin has no params schema");
        const ParamSpec* spec = schema_->find(key);
        if (!spec)
            throw SchemaError("parameter \"" + key + "\" is read but not declared in the params schema");
        if (spec->type != type)
            throw SchemaError(std::string("parameter \"") + key + "\" is read as a " + param_type_name(type) +
                              " but declared a " + param_type_name(spec->type));
        const nlohmann::json* v = find(key);
        if (!v) return spec->default_value;
        const std::string problem = param_problem(*spec, *v);
        if (!problem.empty()) throw ConfigError("/" + key, problem);
        return *v;
    }
    // The getters with a default are for plugins without a schema: with one,
    // the default and range would be written twice.
    void undeclared(const std::string& key, const char* getter) const {
        if (schema_)
            throw SchemaError(std::string(getter) + "(\"" + key +
                              "\", ...) gives a default, but the plugin has a params schema: read it with " +
                              getter + "(\"" + key + "\")");
    }
    const nlohmann::json* find(const std::string& key) {
        known_.insert(key);
        auto it = json_.find(key);
        if (it == json_.end() || it->is_null()) return nullptr;
        return &*it;
    }
    static std::string num(double x) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", x);
        return buf;
    }

    nlohmann::json json_;
    const ParamsSchema* schema_ = nullptr;
    std::set<std::string> known_;
};

}  // namespace pednav::sdk
