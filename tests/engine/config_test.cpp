// SPDX-License-Identifier: Apache-2.0
// Config errors: create fails with a status and err.where pointing at the
// offending key (a JSON pointer into the config).
#include <doctest/doctest.h>

#include <pthread.h>

#include <fstream>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

struct Expect {
    pn_status_t status;
    std::string where;
};

Expect create_fails(const std::string& config, const std::vector<std::string>& dirs = {fixture_dir("good")}) {
    Engine e(config, dirs);
    CHECK(e.get() == nullptr);
    CHECK(e.error().code == e.status());
    CHECK(e.error().message[0] != '\0');
    return {e.status(), e.error().where};
}

}  // namespace

TEST_CASE("broken JSON fails with PN_E_INVALID_CONFIG") {
    Engine e("{\"format\": \"pednav-config/1\", ", {fixture_dir("good")});
    CHECK(e.status() == PN_E_INVALID_CONFIG);
    CHECK(e.get() == nullptr);
    CHECK(contains(e.error().message, "JSON"));
}

TEST_CASE("unknown keys fail with PN_E_INVALID_CONFIG and the key's JSON pointer") {
    auto doc = nlohmann::json::parse(make_config({{"step_detector", "org.pednav.test.counting_steps"}}));
    SUBCASE("top level") {
        doc["mout"] = "foot";
        const auto r = create_fails(doc.dump());
        CHECK(r.status == PN_E_INVALID_CONFIG);
        CHECK(r.where == "/mout");
    }
    SUBCASE("role") {
        doc["pipelines"]["foot"]["step_detektor"] = doc["pipelines"]["foot"]["step_detector"];
        const auto r = create_fails(doc.dump());
        CHECK(r.status == PN_E_INVALID_CONFIG);
        CHECK(r.where == "/pipelines/foot/step_detektor");
    }
    SUBCASE("stage") {
        doc["pipelines"]["foot"]["step_detector"]["plugn"] = "x";
        const auto r = create_fails(doc.dump());
        CHECK(r.status == PN_E_INVALID_CONFIG);
        CHECK(r.where == "/pipelines/foot/step_detector/plugn");
    }
    SUBCASE("reader settings (\"input\"): a key and a type") {
        doc["input"] = {{"colum_map", nlohmann::json::object()}};
        auto r = create_fails(doc.dump());
        CHECK(r.status == PN_E_INVALID_CONFIG);
        CHECK(r.where == "/input/colum_map");
        doc["input"] = {{"format", 3}};
        r = create_fails(doc.dump());
        CHECK(r.where == "/input/format");
    }
    SUBCASE("plugin params (bad_params): the plugin rejects a key it does not know") {
        doc["pipelines"]["foot"]["step_detector"]["params"] = {{"every_nn", 3}};
        const auto r = create_fails(doc.dump());
        CHECK(r.status == PN_E_INVALID_CONFIG);
        CHECK(r.where == "/pipelines/foot/step_detector/params/every_nn");
    }
}

TEST_CASE("a param out of range names the param") {
    const auto r =
        create_fails(make_config({{"step_detector", "org.pednav.test.counting_steps", {{"every_n", 0}}}}));
    CHECK(r.status == PN_E_INVALID_CONFIG);
    CHECK(r.where == "/pipelines/foot/step_detector/params/every_n");
}

TEST_CASE("a wrong format string names /format") {
    auto doc = nlohmann::json::parse(make_config({{"step_detector", "org.pednav.test.counting_steps"}}));
    doc["format"] = "pednav-config/0";
    const auto r = create_fails(doc.dump());
    CHECK(r.status == PN_E_INVALID_CONFIG);
    CHECK(r.where == "/format");
}

TEST_CASE("an unknown plugin id fails with PN_E_NOT_FOUND at .../plugin") {
    const auto r = create_fails(make_config(
        {{"step_detector", "org.pednav.test.counting_steps"}, {"position_filter", "org.example.nothing"}}));
    CHECK(r.status == PN_E_NOT_FOUND);
    CHECK(r.where == "/pipelines/foot/position_filter/plugin");
}

TEST_CASE("a plugin whose library was rejected fails with PN_E_NOT_FOUND at .../plugin") {
    SUBCASE("library-level rejection (ABI major)") {
        const auto r = create_fails(make_config({{"position_filter", "org.pednav.test.wrong_major_field"}}),
                                    {fixture_dir("good"), fixture_dir("wrong_major_field")});
        CHECK(r.status == PN_E_NOT_FOUND);
        CHECK(r.where == "/pipelines/foot/position_filter/plugin");
    }
    SUBCASE("descriptor-level rejection says why") {
        Engine e(make_config({{"position_filter", "org.pednav.test.too_small_descriptor"}}, "chest"),
                 {fixture_dir("too_small_descriptor")});
        CHECK(e.status() == PN_E_NOT_FOUND);
        CHECK(std::string(e.error().where) == "/pipelines/chest/position_filter/plugin");
        CHECK(contains(e.error().message, "rejected"));
        CHECK(contains(e.error().message, "struct_size"));
    }
}

TEST_CASE("a plugin of another kind than its role fails at .../plugin") {
    const auto r = create_fails(make_config({{"position_filter", "org.pednav.test.counting_steps"}}));
    CHECK(r.status == PN_E_INVALID_CONFIG);
    CHECK(r.where == "/pipelines/foot/position_filter/plugin");
}

TEST_CASE("a config without a pipeline for its mount fails with PN_E_NOT_FOUND") {
    auto doc =
        nlohmann::json::parse(make_config({{"step_detector", "org.pednav.test.counting_steps"}}, "chest"));
    doc["mount"] = "foot";
    const auto r = create_fails(doc.dump());
    CHECK(r.status == PN_E_NOT_FOUND);
    CHECK(r.where == "/pipelines/foot");
}

TEST_CASE("create rejects bad arguments without crashing") {
    pn_engine_t* engine = reinterpret_cast<pn_engine_t*>(0x1);
    pn_error_t err = make_error();
    CHECK(pn_engine_create(nullptr, &engine, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(engine == nullptr);
    pn_engine_create_info_t info;
    std::memset(&info, 0, sizeof info);
    info.abi_version = (2u << 16);
    info.struct_size = sizeof info;
    info.config_json = "{}";
    CHECK(pn_engine_create(&info, &engine, nullptr) == PN_E_ABI_MISMATCH);
    CHECK(engine == nullptr);
    pn_engine_destroy(nullptr);
}

TEST_CASE("the engine judges the shared config cases as the config format's JSON Schema does") {
    std::ifstream in(PEDNAV_CONFIG_CASES);
    REQUIRE_MESSAGE(in.good(), "missing " << PEDNAV_CONFIG_CASES);
    const nlohmann::json cases = nlohmann::json::parse(in);
    const nlohmann::json& base = cases.at("base");
    for (const auto& patch : cases.at("valid")) {
        nlohmann::json doc = base;
        doc.merge_patch(patch);
        Engine e(doc.dump(), {fixture_dir("good")});
        CHECK_MESSAGE(e.status() == PN_OK, doc.dump() << ": " << e.error().where << ": " << e.error().message);
    }
    for (const auto& c : cases.at("invalid")) {
        nlohmann::json doc = base;
        doc.merge_patch(c.at("patch"));
        const auto r = create_fails(doc.dump());
        CHECK_MESSAGE(r.status == PN_E_INVALID_CONFIG, doc.dump());
        CHECK_MESSAGE(r.where == c.at("where").get<std::string>(), doc.dump());
    }
}

namespace {

// The config of the counting fixture with `params` spliced in as raw text.
std::string config_with_params_text(const std::string& params_text) {
    return "{\"format\": \"pednav-config/1\", \"mount\": \"foot\", \"pipelines\": {\"foot\": {\"step_detector\": "
           "{\"plugin\": \"org.pednav.test.counting_steps\", \"params\": " +
           params_text + "}}}}";
}

struct ThreadResult {
    std::string config;
    pn_status_t status = PN_OK;
    std::string where, message;
};

void* create_on_thread(void* arg) {
    auto* r = static_cast<ThreadResult*>(arg);
    Engine e(r->config, {fixture_dir("good")});
    r->status = e.status();
    r->where = e.error().where;
    r->message = e.error().message;
    return nullptr;
}

// Creates the engine on a thread with a stack of `stack_bytes` (a mobile worker's 512 KiB).
ThreadResult create_on_small_stack(const std::string& config, size_t stack_bytes) {
    ThreadResult r;
    r.config = config;
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, stack_bytes);
    pthread_t thread;
    REQUIRE(pthread_create(&thread, &attr, create_on_thread, &r) == 0);
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attr);
    return r;
}

}  // namespace

TEST_CASE("regression (issue 18): deep nesting is refused naming where, even on a 512 KiB thread") {
    const std::string deep_5000 = std::string(5000, '[') + std::string(5000, ']');
    const ThreadResult params = create_on_small_stack(
        config_with_params_text("{\"every_n\": 5, \"x\": " + deep_5000 + "}"), 512 * 1024);
    CHECK(params.status == PN_E_INVALID_CONFIG);
    CHECK(contains(params.message, "nested deeper than 64 levels"));
    CHECK(contains(params.where, "/pipelines/foot/step_detector/params/x/0/0/0"));

    std::string text = config_with_params_text("{\"every_n\": 5}");
    text.insert(1, "\"description\": " + std::string(60000, '[') + std::string(60000, ']') + ", ");
    const ThreadResult description = create_on_small_stack(text, 512 * 1024);
    CHECK(description.status == PN_E_INVALID_CONFIG);
    CHECK(contains(description.where, "/description/0/0"));

    // 60 levels in all are allowed: the bound is not below what a config may need.
    const ThreadResult shallow = create_on_small_stack(
        config_with_params_text("{\"every_n\": 5, \"x\": " + std::string(55, '[') + std::string(55, ']') + "}"),
        512 * 1024);
    CHECK_FALSE(contains(shallow.message, "nested deeper"));
}

TEST_CASE("regression (issue 18): duplicate keys, 1e400 and an array config are invalid configs naming the key") {
    SUBCASE("duplicate key") {
        Engine e(config_with_params_text("{\"every_n\": 5, \"every_n\": 7}"), {fixture_dir("good")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK(std::string(e.error().where) == "/pipelines/foot/step_detector/params/every_n");
        CHECK(contains(e.error().message, "duplicate key \"every_n\""));
    }
    SUBCASE("a number out of range") {
        Engine e(config_with_params_text("{\"every_n\": 1e400}"), {fixture_dir("good")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK(std::string(e.error().where) == "/pipelines/foot/step_detector/params/every_n");
        CHECK(contains(e.error().message, "out of range"));
    }
    SUBCASE("an array") {
        Engine e("[" + config_with_params_text("{}") + "]", {fixture_dir("good")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK(contains(e.error().message, "config must be a JSON object, not an array"));
    }
    SUBCASE("ill-formed UTF-8: the message stays printable text") {
        Engine e(config_with_params_text("{\"every_n\": 5, \"name\": \"a\xff\xfe\"}"), {fixture_dir("good")});
        CHECK(e.status() == PN_E_INVALID_CONFIG);
        CHECK(contains(e.error().message, "ill-formed UTF-8"));
        for (const char* c = e.error().message; *c; ++c) CHECK(static_cast<unsigned char>(*c) < 0x80);
    }
}
