// SPDX-License-Identifier: Apache-2.0
// Plugins that misbehave at run time: the engine names the plugin and what it
// did, keeps what was computed before, and resets the instance or stops the
// pipeline as the stage's "on_failure" says; a call over the stage's
// "call_budget_ms" is a warning naming the plugin, or stops the pipeline
// with "over_budget": "stop". (Crashes and _exit inside a plugin cannot be
// contained in-process: tests/cli checks that `pednav run` reports them.)
#include <doctest/doctest.h>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

// A config with one stage whose policy keys are set next to "plugin".
std::string config_with_policy(const std::string& role, const std::string& plugin, const nlohmann::json& params,
                               const nlohmann::json& policy) {
    nlohmann::json doc = nlohmann::json::parse(make_config({{role, plugin, params}}));
    for (auto it = policy.begin(); it != policy.end(); ++it) doc["pipelines"]["foot"][role][it.key()] = it.value();
    return doc.dump();
}

size_t warnings_containing(const nlohmann::json& d, const std::string& text) {
    size_t n = 0;
    for (const auto& w : d["warnings"]) n += contains(w.get<std::string>(), text);
    return n;
}

}  // namespace

TEST_CASE("on_failure \"stop\": the first failure stops the pipeline, later pushes say who stopped it") {
    Engine e(config_with_policy("step_detector", "org.pednav.test.throws", {{"throw_at", 50}, {"every_n", 10}},
                                {{"on_failure", "stop"}}),
             {fixture_dir("throws")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    REQUIRE(push(e, walk(0, 60), &err) == PN_E_INTERNAL);
    CHECK(std::string(err.where) == "foot/step_detector");
    CHECK_MESSAGE(contains(err.message, "(org.pednav.test.throws) failed in process: plugin threw: fixture failure at sample 50"),
                  err.message);
    CHECK_MESSAGE(contains(err.message, "on_failure is \"stop\""), err.message);
    // Steps at samples 10..40 were computed before the failure and stay.
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 4);

    err = make_error();
    CHECK(push(e, walk(60, 10), &err) == PN_E_BAD_STATE);
    CHECK(std::string(err.where) == "foot/step_detector");
    CHECK_MESSAGE(contains(err.message, "the pipeline is stopped (pn_engine_reset starts it again)"), err.message);
    CHECK_MESSAGE(contains(err.message, "fixture failure at sample 50"), err.message);
    CHECK(pn_engine_flush(e.get(), &err) == PN_E_BAD_STATE);
    CHECK(e.poll_all().empty());  // nothing was processed after the stop
    auto d = e.describe();
    CHECK(d["pipeline"]["stopped"] == true);
    CHECK(d["pipeline"]["stopped_by"]["instance"] == "foot/step_detector");
    CHECK(d["pipeline"]["stages"][0]["failures"] == 1);
    CHECK(d["pipeline"]["stages"][0]["resets"] == 0);
    CHECK(d["pipeline"]["stages"][0]["on_failure"] == "stop");

    // A reset starts it again from a fresh instance.
    REQUIRE(pn_engine_reset(e.get(), &err) == PN_OK);
    REQUIRE(push(e, walk(0, 31)) == PN_OK);
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 3);
    CHECK(e.describe()["pipeline"]["stopped"] == false);
}

TEST_CASE("on_failure \"reset\" (the default): the instance is reset and the pipeline goes on") {
    Engine e(make_config({{"step_detector", "org.pednav.test.throws", {{"throw_at", 5}, {"every_n", 10}}}}),
             {fixture_dir("throws")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    REQUIRE(push(e, walk(0, 30), &err) == PN_E_INTERNAL);
    CHECK_MESSAGE(contains(err.message, "(the instance was reset)"), err.message);
    const auto d = e.describe();
    CHECK(d["pipeline"]["stopped"] == false);
    CHECK(d["pipeline"]["stages"][0]["resets"] == 1);
    CHECK(d["pipeline"]["stages"][0]["on_failure"] == "reset");
    // The fresh instance counts from the reset: its 5th sample would throw again, these are its 1st to 4th.
    CHECK(push(e, walk(30, 4)) == PN_OK);
}

TEST_CASE("an exception in create, flush or latency_ns is a status naming the plugin, never std::terminate") {
    SUBCASE("create: pn_engine_create fails naming the plugin and the instance") {
        Engine e(make_config({{"step_detector", "org.pednav.test.throws", {{"throw_in", "create"}}}}),
                 {fixture_dir("throws")});
        CHECK(e.status() == PN_E_INTERNAL);
        CHECK(std::string(e.error().where) == "/pipelines/foot/step_detector/plugin");
        CHECK_MESSAGE(contains(e.error().message, "org.pednav.test.throws (foot/step_detector) failed in create: plugin "
                                                  "threw: fixture failure in create"),
                      e.error().message);
    }
    SUBCASE("flush") {
        Engine e(make_config({{"step_detector", "org.pednav.test.throws", {{"throw_in", "flush"}}}}),
                 {fixture_dir("throws")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        REQUIRE(push(e, walk(0, 100)) == PN_OK);
        pn_error_t err = make_error();
        CHECK(pn_engine_flush(e.get(), &err) == PN_E_INTERNAL);
        CHECK(std::string(err.where) == "foot/step_detector");
        CHECK_MESSAGE(contains(err.message, "failed in flush: plugin threw: fixture failure in flush"), err.message);
        CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 10);  // samples 10 .. 100: the last one released by flush
    }
    SUBCASE("latency_ns: the SDK answers -1, which the engine refuses naming the plugin") {
        Engine e(make_config({{"step_detector", "org.pednav.test.throws", {{"throw_in", "latency"}}}}),
                 {fixture_dir("throws")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK_MESSAGE(contains(e.error().message, "foot/step_detector (org.pednav.test.throws) declares a look-ahead of -1e-09 s"),
                      e.error().message);
    }
}

TEST_CASE("a covariance that is not positive semi-definite, or not symmetric, is refused with PN_E_NUMERIC") {
    for (const char* key : {"non_psd_at", "asymmetric_at"}) {
        CAPTURE(key);
        Engine e(make_config({{"position_filter", "org.pednav.test.emits_nan", {{"nan_at", 1000000}, {key, 20}}}}),
                 {fixture_dir("emits_nan")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        pn_error_t err = make_error();
        CHECK(push(e, walk(0, 30), &err) == PN_E_NUMERIC);
        CHECK(std::string(err.where) == "foot/position_filter");
        const std::string why = std::string(key) == "non_psd_at" ? "cov_enu_m2[1] is 2 (a correlation above 1: not positive semi-definite)"
                                                                  : "cov_enu_m2[1] is 0.5 (not symmetric";
        CHECK_MESSAGE(contains(err.message, why), err.message);
        CHECK_MESSAGE(contains(err.message, "(org.pednav.test.emits_nan)"), err.message);
        CHECK(of_type(e.poll_all(), PN_REC_POSITION).size() == 19);  // the positions before it stay
        CHECK(e.describe()["pipeline"]["stages"][0]["resets"] == 1);
        // The reset instance goes on from the sample that failed: samples 20 .. 29 (30 waits).
        CHECK(push(e, walk(21, 10)) == PN_OK);
        const auto after = of_type(e.poll_all(), PN_REC_POSITION);
        REQUIRE(after.size() == 10);
        CHECK(after[0].header.t_ns == sample_t_ns(20));
        CHECK(after[0].position.pos_enu_m[0] == 1.0);
    }
}

TEST_CASE("a call over call_budget_ms is a warning naming the plugin, repeated only at the 2nd, 4th, 8th ... overrun") {
    // Every call from sample 50 on sleeps 12 ms against a budget of 4 ms.
    Engine e(config_with_policy("step_detector", "org.pednav.test.rt_slow",
                                {{"slow_at", 50}, {"slow_every", 1}, {"sleep_ms", 12.0}}, {{"call_budget_ms", 4}}),
             {fixture_dir("rt_slow")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    CHECK(push(e, walk(0, 70), &err) == PN_OK);  // samples 0 .. 68 are processed, the 50th to 69th slowly
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 6);
    const auto d = e.describe();
    const auto& stage = d["pipeline"]["stages"][0];
    const uint64_t over = stage["calls_over_budget"];
    CHECK(over >= 20);  // a busy machine may add a slow ordinary call, never remove one
    CHECK(stage["slowest_call_ms"].get<double>() >= 12.0);
    CHECK(stage["call_budget_ms"] == 4.0);
    size_t expected_warnings = 0;
    for (uint64_t n = 1; n <= over; n *= 2) ++expected_warnings;
    CHECK(warnings_containing(d, "foot/step_detector: (org.pednav.test.rt_slow) took ") == expected_warnings);
    CHECK(warnings_containing(d, "over its call_budget_ms of 4.000 ms (1 call over budget)") == 1);
    CHECK(d["pipeline"]["stopped"] == false);
}

TEST_CASE("over_budget \"stop\": a call over the budget stops the pipeline, naming the plugin and the time") {
    Engine e(config_with_policy("step_detector", "org.pednav.test.rt_slow", {{"slow_at", 50}, {"sleep_ms", 40.0}},
                                {{"call_budget_ms", 20}, {"over_budget", "stop"}}),
             {fixture_dir("rt_slow")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    CHECK(push(e, walk(0, 70), &err) == PN_E_BAD_STATE);
    CHECK(std::string(err.where) == "foot/step_detector");
    CHECK_MESSAGE(contains(err.message, "(org.pednav.test.rt_slow) took "), err.message);
    CHECK_MESSAGE(contains(err.message, "ms in process, over its call_budget_ms of 20.000 ms"), err.message);
    CHECK_MESSAGE(contains(err.message, "over_budget is \"stop\": the pipeline is stopped"), err.message);
    const auto steps = of_type(e.poll_all(), PN_REC_STEP);
    REQUIRE(steps.size() == 5);  // the steps of the 10th .. 40th samples, and of the 50th (its slow call emitted it)
    CHECK(steps[3].header.t_ns == sample_t_ns(39));
    CHECK(push(e, walk(70, 10), &err) == PN_E_BAD_STATE);
    CHECK_MESSAGE(contains(err.message, "the pipeline is stopped"), err.message);
    CHECK(e.describe()["pipeline"]["stopped_by"]["instance"] == "foot/step_detector");
}

TEST_CASE("a config cannot name a library path: plugin ids only, from the plugin directories") {
    for (const char* id : {"/tmp/libpnp_evil.so", "../lib/libpnp_foot_ekf.so", "libpnp_good.so"}) {
        CAPTURE(id);
        Engine e(make_config({{"step_detector", id}}), {fixture_dir("good")});
        CHECK(e.status() == PN_E_NOT_FOUND);
        CHECK(std::string(e.error().where) == "/pipelines/foot/step_detector/plugin");
        CHECK_MESSAGE(contains(e.error().message, "looks like a file path: a config names plugin ids"), e.error().message);
    }
}
