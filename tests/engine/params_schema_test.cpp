// SPDX-License-Identifier: Apache-2.0
// The engine checks a stage's params against its plugin's parameter schema
// before create (fixture library "schema"): what it refuses, with which
// status, pointer and message, and that the schema's defaults are what the
// plugin runs with.
#include <doctest/doctest.h>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

const std::string kSteps = "org.pednav.test.schema_steps";
const std::string kParamsAt = "/pipelines/foot/step_detector/params/";

Engine schema_engine(const std::string& plugin, const nlohmann::json& params = nlohmann::json::object()) {
    return Engine(make_config({{"step_detector", plugin, params}}), {fixture_dir("schema")});
}

struct Refusal {
    pn_status_t status;
    std::string where, message;
};

Refusal refused(const std::string& plugin, const nlohmann::json& params) {
    const Engine e = schema_engine(plugin, params);
    CHECK(e.get() == nullptr);
    return {e.status(), e.error().where, e.error().message};
}

// The gait phases and steps of 8 samples through a created engine.
std::vector<pn_output_t> gait_phases(const Engine& e) {
    REQUIRE(e.get() != nullptr);
    REQUIRE(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_GAIT_PHASE) | PN_REC_MASK(PN_REC_STEP)) ==
            PN_OK);
    REQUIRE(push(e, walk(0, 8)) == PN_OK);
    pn_error_t err = make_error();
    REQUIRE(pn_engine_flush(e.get(), &err) == PN_OK);
    return e.poll_all();
}

}  // namespace

TEST_CASE("absent params take the schema's defaults, given ones reach the plugin") {
    const Engine defaults = schema_engine(kSteps);
    INFO(defaults.error().message);
    const auto d = gait_phases(defaults);
    REQUIRE(of_type(d, PN_REC_GAIT_PHASE).size() == 8);
    CHECK(of_type(d, PN_REC_GAIT_PHASE)[0].gait_phase.statistic == 0.5);  // gain's default
    CHECK(of_type(d, PN_REC_GAIT_PHASE)[0].gait_phase.stance == 1);       // stance's default
    CHECK(of_type(d, PN_REC_STEP).size() == 2);                           // every_n 4

    const Engine given =
        schema_engine(kSteps, {{"gain", 1.25}, {"every_n", 3}, {"stance", false}, {"sign", "negative"}});
    const auto g = gait_phases(given);
    REQUIRE(of_type(g, PN_REC_GAIT_PHASE).size() == 8);
    CHECK(of_type(g, PN_REC_GAIT_PHASE)[0].gait_phase.statistic == -1.25);
    CHECK(of_type(g, PN_REC_GAIT_PHASE)[0].gait_phase.stance == 0);
    CHECK(of_type(g, PN_REC_STEP).size() == 2);  // samples 3 and 6

    // An integer written with a zero fraction is an integer (JSON Schema); null is absent.
    const auto n = gait_phases(schema_engine(kSteps, {{"every_n", 2.0}, {"gain", nullptr}}));
    REQUIRE(of_type(n, PN_REC_GAIT_PHASE).size() == 8);
    CHECK(of_type(n, PN_REC_STEP).size() == 4);
    CHECK(of_type(n, PN_REC_GAIT_PHASE)[0].gait_phase.statistic == 0.5);
}

TEST_CASE("a value out of range is refused naming key, value and range with its unit") {
    Refusal r = refused(kSteps, {{"gain", 5}});
    CHECK(r.status == PN_E_INVALID_CONFIG);
    CHECK(r.where == kParamsAt + "gain");
    CHECK(r.message == kSteps + ": gain is 5, outside [0, 2] m");
    r = refused(kSteps, {{"gain", -0.25}});
    CHECK(r.message == kSteps + ": gain is -0.25, outside [0, 2] m");
    r = refused(kSteps, {{"every_n", 1001}});
    CHECK(r.where == kParamsAt + "every_n");
    CHECK(r.message == kSteps + ": every_n is 1001, outside [1, 1000]");
}

TEST_CASE("a value of the wrong type or not in the enum is refused") {
    Refusal r = refused(kSteps, {{"gain", "0.5"}});
    CHECK(r.status == PN_E_INVALID_CONFIG);
    CHECK(r.where == kParamsAt + "gain");
    CHECK(r.message == kSteps + ": gain must be a number, not \"0.5\"");
    r = refused(kSteps, {{"every_n", 2.5}});
    CHECK(r.where == kParamsAt + "every_n");
    CHECK(r.message == kSteps + ": every_n must be an integer, not 2.5");
    r = refused(kSteps, {{"stance", "yes"}});
    CHECK(r.message == kSteps + ": stance must be true or false, not \"yes\"");
    r = refused(kSteps, {{"sign", "up"}});
    CHECK(r.where == kParamsAt + "sign");
    CHECK(r.message == kSteps + ": sign is \"up\", not one of positive, negative");
    r = refused(kSteps, {{"sign", 1}});
    CHECK(r.message == kSteps + ": sign must be a string, not 1");
}

TEST_CASE("an unknown key is refused at its pointer, with the nearest declared key") {
    Refusal r = refused(kSteps, {{"gian", 0.5}});
    CHECK(r.status == PN_E_INVALID_CONFIG);
    CHECK(r.where == kParamsAt + "gian");
    CHECK(r.message == kSteps + ": unknown parameter \"gian\" (did you mean \"gain\"?)");
    r = refused(kSteps, {{"a/b~c", 1}});
    CHECK(r.where == kParamsAt + "a~1b~0c");  // RFC 6901 escapes
    CHECK(contains(r.message, "pednav plugins --params"));
}

TEST_CASE("a schema that is not JSON or outside the subset is refused at create, naming the plugin") {
    Refusal r = refused("org.pednav.test.schema_not_json", nlohmann::json::object());
    CHECK(r.status == PN_E_INTERNAL);
    CHECK(r.where == "/pipelines/foot/step_detector/plugin");
    CHECK(contains(r.message,
                   "plugin org.pednav.test.schema_not_json cannot be configured: its params schema is not "
                   "valid JSON"));
    r = refused("org.pednav.test.schema_outside_subset", nlohmann::json::object());
    CHECK(r.status == PN_E_INTERNAL);
    CHECK(r.where == "/pipelines/foot/step_detector/plugin");
    CHECK(contains(r.message, "org.pednav.test.schema_outside_subset"));
    CHECK(contains(r.message,
                   "property \"gain\" uses keyword \"exclusiveMinimum\", outside the supported subset"));
    // The other plugins of the same library are unaffected.
    CHECK(schema_engine(kSteps).status() == PN_OK);
}

TEST_CASE("plugin code that disagrees with its schema fails at create with PN_E_INTERNAL, naming the key") {
    Refusal r = refused("org.pednav.test.schema_undeclared", nlohmann::json::object());
    CHECK(r.status == PN_E_INTERNAL);
    CHECK(contains(r.message, "parameter \"offset\" is read but not declared in the params schema"));
    r = refused("org.pednav.test.schema_unread", nlohmann::json::object());
    CHECK(r.status == PN_E_INTERNAL);
    CHECK(contains(r.message,
                   "parameter \"gain\" is declared in the params schema but the plugin never reads it"));
}

TEST_CASE("describe carries each plugin's schema as JSON") {
    const Engine e = schema_engine(kSteps);
    const nlohmann::json d = e.describe();
    REQUIRE(d.is_object());
    bool seen = false;
    for (const auto& p : d.at("plugins")) {
        if (p.at("id") != kSteps) continue;
        seen = true;
        CHECK(p.at("params_schema").at("properties").at("gain").at("maximum") == 2);
    }
    CHECK(seen);
}
