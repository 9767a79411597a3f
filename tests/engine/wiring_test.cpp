// SPDX-License-Identifier: Apache-2.0
// A pipeline that cannot work is refused at create, naming the stage and the
// record type it needs, instead of returning a wrong track with PN_OK: the
// plugins declare what they cannot do without ("needs:gait_phase").
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "test_support.hpp"

using namespace pednav::test;

namespace {

nlohmann::json foot_preset() {
    std::ifstream in(std::string(PEDNAV_CONFIG_DIR) + "/foot.json");
    REQUIRE_MESSAGE(in.good(), "the foot preset is missing at " << PEDNAV_CONFIG_DIR << "/foot.json");
    std::stringstream text;
    text << in.rdbuf();
    return nlohmann::json::parse(text.str());
}

}  // namespace

TEST_CASE("a step detector emitting STEP where the foot EKF needs GAIT_PHASE is refused") {
    // The README's example detector emits STEP only; org.pednav.test.throws does too.
    nlohmann::json cfg = foot_preset();
    cfg["pipelines"]["foot"]["step_detector"] = {{"plugin", "org.pednav.test.throws"}, {"params", {{"throw_at", 1000000}}}};
    Engine e(cfg.dump(), {PEDNAV_PLUGIN_OUTPUT_DIR, fixture_dir("throws")});
    CHECK(e.status() == PN_E_INVALID_CONFIG);
    CHECK(std::string(e.error().where) == "/pipelines/foot/position_filter/plugin");
    const std::string msg = e.error().message;
    CHECK_MESSAGE(contains(msg, "foot/position_filter (org.pednav.foot.ekf15) needs gait_phase records"), msg);
    CHECK_MESSAGE(contains(msg, "foot/step_detector (org.pednav.test.throws) produces step"), msg);
}

TEST_CASE("a foot pipeline without its attitude estimator is refused") {
    nlohmann::json cfg = foot_preset();
    cfg["pipelines"]["foot"].erase("attitude_estimator");
    Engine e(cfg.dump(), {PEDNAV_PLUGIN_OUTPUT_DIR});
    CHECK(e.status() == PN_E_INVALID_CONFIG);
    CHECK(std::string(e.error().where) == "/pipelines/foot/position_filter/plugin");
    CHECK_MESSAGE(contains(e.error().message, "needs attitude records, which no earlier stage"), e.error().message);
}

TEST_CASE("the foot preset itself is wired") {
    Engine e(foot_preset().dump(), {PEDNAV_PLUGIN_OUTPUT_DIR});
    CHECK_MESSAGE(e.status() == PN_OK, e.error().message);
}
