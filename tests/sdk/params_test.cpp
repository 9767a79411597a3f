// SPDX-License-Identifier: Apache-2.0
// The SDK's parameter schema subset (params_schema.hpp) and Params with and
// without a schema (params.hpp).
#include <doctest/doctest.h>

#include <string>

#include <pednav_sdk/params.hpp>

using pednav::sdk::ConfigError;
using pednav::sdk::Params;
using pednav::sdk::ParamsSchema;
using pednav::sdk::ParamType;
using pednav::sdk::SchemaError;

namespace {

const char* const kSchema = R"json({
  "type": "object", "additionalProperties": false, "title": "t", "description": "d",
  "properties": {
    "window_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 2, "default": 0.06,
                 "description": "centred window"},
    "count": {"type": "integer", "minimum": 1, "default": 3, "description": "a count"},
    "on": {"type": "boolean", "default": false, "description": "a switch"},
    "mode": {"type": "string", "enum": ["fast", "exact"], "default": "exact", "description": "a mode"},
    "label": {"type": "string", "default": "", "description": "any text"}
  }
})json";

const ParamsSchema& schema() {
    static const ParamsSchema s = ParamsSchema::parse(kSchema);
    return s;
}

// The SchemaError message of parsing `text`, or "" when it parses.
std::string schema_error(const std::string& text) {
    try {
        ParamsSchema::parse(text);
    } catch (const SchemaError& e) {
        return e.what();
    }
    return "";
}

std::string with_property(const std::string& property) {
    return R"({"type": "object", "additionalProperties": false, "properties": {"k": )" + property + "}}";
}

bool has(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace

TEST_CASE("a schema in the subset parses into sorted parameters with type, unit, range, default, meaning") {
    const auto& p = schema().params();
    REQUIRE(p.size() == 5);
    CHECK(p[0].key == "count");
    CHECK(p[1].key == "label");
    CHECK(p[4].key == "window_s");
    const auto* w = schema().find("window_s");
    REQUIRE(w);
    CHECK(w->type == ParamType::number);
    CHECK(w->unit == "s");
    CHECK(w->has_minimum);
    CHECK(w->minimum == 0.0);
    CHECK(w->maximum == 2.0);
    CHECK(w->default_value.get<double>() == 0.06);
    CHECK(w->description == "centred window");
    CHECK(pednav::sdk::range_text(*w) == "[0, 2]");
    const auto* c = schema().find("count");
    CHECK(c->has_minimum);
    CHECK_FALSE(c->has_maximum);
    CHECK(pednav::sdk::range_text(*c) == ">= 1");
    CHECK(pednav::sdk::range_text(*schema().find("mode")) == "one of fast, exact");
    CHECK(pednav::sdk::range_text(*schema().find("label")) == "");
    CHECK(schema().find("nothing") == nullptr);
}

TEST_CASE("schemas outside the subset are refused, naming what is wrong") {
    CHECK(has(schema_error("{\"type\": "), "params schema is not valid JSON"));
    CHECK(has(schema_error("[]"), "must be a JSON object"));
    CHECK(has(schema_error(R"({"additionalProperties": false, "properties": {}})"),
              "needs \"type\": \"object\""));
    CHECK(has(schema_error(R"({"type": "object", "properties": {}})"),
              "needs \"additionalProperties\": false"));
    CHECK(has(schema_error(R"({"type": "object", "additionalProperties": true, "properties": {}})"),
              "needs \"additionalProperties\": false"));
    CHECK(has(schema_error(R"({"type": "object", "additionalProperties": false})"),
              "needs a \"properties\" object"));
    CHECK(has(schema_error(
                  R"({"type": "object", "additionalProperties": false, "properties": {}, "required": []})"),
              "uses keyword \"required\", outside the supported subset"));
    CHECK(has(schema_error(with_property(
                  R"({"type": "number", "default": 1, "description": "d", "exclusiveMinimum": 0})")),
              "property \"k\" uses keyword \"exclusiveMinimum\""));
    CHECK(has(schema_error(with_property(R"({"type": "array", "default": [], "description": "d"})")),
              "property \"k\" needs \"type\": number, integer, boolean or string"));
    CHECK(has(schema_error(with_property(R"({"type": "number", "description": "d"})")),
              "property \"k\" needs a \"default\""));
    CHECK(has(schema_error(with_property(R"({"type": "number", "default": 1})")),
              "property \"k\" needs a \"description\""));
    CHECK(has(schema_error(with_property(R"({"type": "number", "default": 1, "description": ""})")),
              "needs a \"description\""));
    CHECK(has(schema_error(with_property(
                  R"({"type": "number", "minimum": 2, "maximum": 1, "default": 1, "description": "d"})")),
              "\"minimum\" above \"maximum\""));
    CHECK(has(
        schema_error(with_property(R"({"type": "number", "maximum": 1, "default": 3, "description": "d"})")),
        "has a default the schema itself refuses: k is 3, above the maximum 1"));
    CHECK(has(schema_error(
                  with_property(R"({"type": "boolean", "minimum": 0, "default": true, "description": "d"})")),
              "has \"minimum\", which only a number or an integer takes"));
    CHECK(has(schema_error(
                  with_property(R"({"type": "string", "x-unit": "s", "default": "", "description": "d"})")),
              "has \"x-unit\", which only a number or an integer takes"));
    CHECK(has(
        schema_error(with_property(R"({"type": "number", "enum": [1], "default": 1, "description": "d"})")),
        "has \"enum\", which only a string takes"));
    CHECK(has(
        schema_error(with_property(R"({"type": "string", "enum": [], "default": "", "description": "d"})")),
        "\"enum\" must be a non-empty array of strings"));
    CHECK(has(schema_error(
                  with_property(R"({"type": "string", "enum": ["a"], "default": "b", "description": "d"})")),
              "k is \"b\", not one of a"));
    CHECK(schema_error(kSchema).empty());
}

TEST_CASE("param_problem names key, value and range") {
    using pednav::sdk::param_problem;
    const auto& w = *schema().find("window_s");
    CHECK(param_problem(w, 5) == "window_s is 5, outside [0, 2] s");
    CHECK(param_problem(w, 2.0).empty());
    CHECK(param_problem(w, 0).empty());
    CHECK(param_problem(w, true) == "window_s must be a number, not true");
    const auto& c = *schema().find("count");
    CHECK(param_problem(c, 0) == "count is 0, below the minimum 1");
    CHECK(param_problem(c, 4.5) == "count must be an integer, not 4.5");
    CHECK(param_problem(c, 4.0).empty());
    CHECK(param_problem(c, 1e300) == "count must be an integer, not 1e+300");
    CHECK(param_problem(*schema().find("mode"), "slow") == "mode is \"slow\", not one of fast, exact");
    CHECK(param_problem(*schema().find("on"), "true") == "on must be true or false, not \"true\"");
}

TEST_CASE("format_number writes the shortest text that reads back") {
    using pednav::sdk::format_number;
    CHECK(format_number(0.06) == "0.06");
    CHECK(format_number(9.80665) == "9.80665");
    CHECK(format_number(200) == "200");
    CHECK(format_number(1e-5) == "1e-05");
    CHECK(format_number(1e6) == "1e+06");
    CHECK(format_number(0.1 + 0.2) == "0.30000000000000004");
}

TEST_CASE("Params with a schema: the default when absent, the value when given, refused when bad") {
    Params absent("{}", &schema());
    CHECK(absent.number("window_s") == 0.06);
    CHECK(absent.integer("count") == 3);
    CHECK(absent.boolean("on") == false);
    CHECK(absent.text("mode") == "exact");
    CHECK(absent.text("label") == "");
    CHECK_NOTHROW(absent.check_every_declared_read());

    Params given(R"({"window_s": 0.5, "count": 7, "on": true, "mode": "fast", "label": "x"})", &schema());
    CHECK(given.number("window_s") == 0.5);
    CHECK(given.integer("count") == 7);
    CHECK(given.boolean("on") == true);
    CHECK(given.text("mode") == "fast");
    CHECK(given.text("label") == "x");
    CHECK_NOTHROW(given.check_no_unknown_keys());

    Params null_is_absent(R"({"window_s": null})", &schema());
    CHECK(null_is_absent.number("window_s") == 0.06);

    Params bad(R"({"window_s": 5})", &schema());
    try {
        bad.number("window_s");
        FAIL("accepted 5 outside [0, 2]");
    } catch (const ConfigError& e) {
        CHECK(e.where() == "/window_s");
        CHECK(std::string(e.what()) == "window_s is 5, outside [0, 2] s");
    }
    Params unknown(R"({"windw_s": 0.1})", &schema());
    unknown.number("window_s");
    CHECK_THROWS_WITH_AS(unknown.check_no_unknown_keys(), "unknown parameter \"windw_s\"", ConfigError);
}

TEST_CASE("Params with a schema: code that disagrees with the schema is a SchemaError naming the key") {
    Params p("{}", &schema());
    CHECK_THROWS_WITH_AS(p.number("offset"),
                         "parameter \"offset\" is read but not declared in the params schema", SchemaError);
    CHECK_THROWS_WITH_AS(p.boolean("window_s"),
                         "parameter \"window_s\" is read as a boolean but declared a number", SchemaError);
    CHECK_THROWS_AS(p.number("window_s", 0.06, 0.0, 2.0),
                    SchemaError);  // the default and range written twice
    CHECK_THROWS_AS(p.integer("count", 3), SchemaError);
    CHECK_THROWS_AS(p.numbers("window_s", {}), SchemaError);  // arrays are outside the subset
    p.number("window_s");
    p.boolean("on");
    p.text("mode");
    p.text("label");
    CHECK_THROWS_WITH_AS(p.check_every_declared_read(),
                         "parameter \"count\" is declared in the params schema but the plugin never reads it",
                         SchemaError);
}

TEST_CASE("Params without a schema keep the getters with a default and a range") {
    Params p(R"({"gain": 1.5, "n": 4})");
    CHECK(p.schema() == nullptr);
    CHECK(p.number("gain", 1.0, 0.0, 2.0) == 1.5);
    CHECK(p.number("absent", 0.25) == 0.25);
    CHECK(p.integer("n", 1, 1, 10) == 4);
    CHECK(p.boolean("flag", true) == true);
    CHECK_NOTHROW(p.check_no_unknown_keys());
    CHECK_NOTHROW(p.check_every_declared_read());
    CHECK_THROWS_AS(p.number("gain", 1.0, 0.0, 1.0), ConfigError);
    CHECK_THROWS_WITH_AS(p.number("gain"),
                         "parameter \"gain\" is read without a default, but the plugin has no params schema",
                         SchemaError);
}
