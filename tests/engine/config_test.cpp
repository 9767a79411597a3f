// SPDX-License-Identifier: Apache-2.0
// Config errors: create fails with a status and err.where pointing at the
// offending key (a JSON pointer into the config).
#include <doctest/doctest.h>

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
