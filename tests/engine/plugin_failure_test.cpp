// SPDX-License-Identifier: Apache-2.0
// A misbehaving plugin yields a clear error from push, never a crash: the
// outputs before the failure stay, and the engine keeps working afterwards.
#include <doctest/doctest.h>

#include "test_support.hpp"

using namespace pednav::test;

TEST_CASE("a plugin that throws makes push return PN_E_INTERNAL naming the instance") {
    Engine e(make_config({{"step_detector", "org.pednav.test.throws", {{"throw_at", 50}, {"every_n", 10}}}}),
             {fixture_dir("throws")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    REQUIRE(push(e, walk(0, 40)) == PN_OK);
    auto kept = of_type(e.poll_all(), PN_REC_STEP);
    CHECK(kept.size() == 3);  // samples 10, 20, 30; sample 40 waits for a later time

    pn_error_t err = make_error();
    const pn_status_t s = push(e, walk(40, 20), &err);
    REQUIRE(s == PN_E_INTERNAL);
    CHECK(err.code == PN_E_INTERNAL);
    CHECK(std::string(err.where) == "foot/step_detector");
    CHECK_MESSAGE(contains(err.message, "fixture failure at sample 50"), err.message);
    CHECK(err.detail >= 9);  // not before the sample whose processing failed (index 9 of this call)
    CHECK(err.detail < 20);
    // Outputs produced before the failure are still there.
    for (const auto& o : e.poll_all())
        if (o.header.type == PN_REC_STEP) kept.push_back(o);
    REQUIRE(kept.size() == 4);
    CHECK(kept[3].header.t_ns == sample_t_ns(39));

    // Later pushes work again (the instance was reset or carries on: either
    // way it counts 40 more samples after sample 50, fewer than throw_at).
    const size_t next = 40 + static_cast<size_t>(err.detail) + 1;
    REQUIRE(push(e, walk(next, 90 - next)) == PN_OK);
    REQUIRE(pn_engine_flush(e.get(), &err) == PN_OK);
    const auto later = of_type(e.poll_all(), PN_REC_STEP);
    CHECK(later.size() == 4);  // samples 60, 70, 80, 90
    for (const auto& o : later) CHECK(o.header.t_ns > sample_t_ns(49));
    const auto d = e.describe();
    CHECK(d["pipeline"]["stages"][0]["failures"] == 1);
}

TEST_CASE("a plugin emitting NaN is refused with PN_E_NUMERIC; the finite outputs before it stay") {
    Engine e(make_config({{"position_filter", "org.pednav.test.emits_nan", {{"nan_at", 20}}}}),
             {fixture_dir("emits_nan")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    pn_error_t err = make_error();
    CHECK(push(e, walk(0, 30), &err) == PN_E_NUMERIC);
    CHECK(std::string(err.where) == "foot/position_filter");
    CHECK_MESSAGE(contains(err.message, "pos_enu_m"), err.message);
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    REQUIRE(pos.size() == 19);
    for (size_t i = 0; i < pos.size(); ++i) {
        CHECK(std::isfinite(pos[i].position.pos_enu_m[0]));
        CHECK(pos[i].position.pos_enu_m[0] == static_cast<double>(i + 1));
    }
    // The engine keeps going on later samples.
    const size_t next = static_cast<size_t>(err.detail) + 1;
    CHECK(push(e, walk(next, 10)) == PN_OK);
    CHECK(!of_type(e.poll_all(), PN_REC_POSITION).empty());
}

TEST_CASE("an output going back in time is refused although only the app reads it") {
    SUBCASE("a position 1 s before the previous one, in process") {
        Engine e(make_config({{"position_filter", "org.pednav.test.emits_nan",
                               {{"nan_at", 1000000}, {"rewind_at", 150}, {"rewind_s", 1.0}}}}),
                 {fixture_dir("emits_nan")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        pn_error_t err = make_error();
        CHECK(push(e, walk(0, 200), &err) == PN_E_OUT_OF_ORDER);
        CHECK(std::string(err.where) == "foot/position_filter");
        CHECK_MESSAGE(contains(err.message, "before its previous position"), err.message);
        const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
        REQUIRE(pos.size() == 150);  // samples 1..150; the rewound one never reaches the app
        for (size_t i = 1; i < pos.size(); ++i) CHECK(pos[i].header.t_ns > pos[i - 1].header.t_ns);
    }
    SUBCASE("t = 0 from flush after the walk") {
        Engine e(make_config({{"position_filter", "org.pednav.test.emits_nan", {{"nan_at", 1000000}, {"flush_at_zero", true}}}}),
                 {fixture_dir("emits_nan")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        REQUIRE(push(e, walk(0, 100)) == PN_OK);
        pn_error_t err = make_error();
        CHECK(pn_engine_flush(e.get(), &err) == PN_E_OUT_OF_ORDER);
        CHECK_MESSAGE(contains(err.message, "at t=0.000000 s, before its previous position"), err.message);
        const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
        REQUIRE(pos.size() == 100);
        CHECK(pos.back().position.pos_enu_m[0] == 100.0);  // the last position is the walk's, not 0,0,0
        CHECK(e.describe()["counters"]["plugin_failures"] == 1);
    }
}
