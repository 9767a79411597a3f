// SPDX-License-Identifier: Apache-2.0
// pn_engine.h threading contract: one thread may push while one other thread
// polls. Every output arrives exactly once and in order.
#include <atomic>
#include <thread>

#include <doctest/doctest.h>

#include "test_support.hpp"

using namespace pednav::test;

TEST_CASE("one thread pushes while another polls: nothing lost, duplicated or reordered") {
    Engine e(make_config({{"step_detector", "org.pednav.test.counting_steps", {{"every_n", 2}}},
                          {"position_filter", "org.pednav.test.step_counter"}}),
             {fixture_dir("good")}, 65536);  // room for every output: none may be dropped
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    constexpr size_t kSamples = 20000;  // 10000 steps -> 30000 outputs
    const auto samples = walk(0, kSamples);
    std::atomic<bool> done{false};
    std::atomic<int> push_failures{0};
    std::thread producer([&] {
        for (size_t i = 0; i < kSamples; i += 50)
            if (pn_engine_push_imu(e.get(), &samples[i], 50, sizeof(pn_imu_t), nullptr) != PN_OK)
                ++push_failures;
        if (pn_engine_flush(e.get(), nullptr) != PN_OK) ++push_failures;
        done = true;
    });
    size_t steps = 0, positions = 0, order_errors = 0;
    int64_t last_t = INT64_MIN;
    double last_north = 0.0;
    pn_output_t o;
    for (;;) {
        const bool finished = done.load();
        while (pn_engine_poll(e.get(), &o) == PN_OK) {
            if (o.header.t_ns < last_t) ++order_errors;
            last_t = o.header.t_ns;
            if (o.header.type == PN_REC_STEP) ++steps;
            if (o.header.type == PN_REC_POSITION) {
                if (o.position.pos_enu_m[1] <= last_north) ++order_errors;
                last_north = o.position.pos_enu_m[1];
                ++positions;
            }
        }
        if (finished) break;
        std::this_thread::yield();
    }
    producer.join();
    CHECK(push_failures == 0);
    CHECK(order_errors == 0);
    CHECK(e.describe()["counters"]["outputs_dropped"] == 0);
    CHECK(steps == kSamples / 2);
    CHECK(positions == kSamples / 2);
    CHECK(last_north == doctest::Approx(0.7 * kSamples / 2));
}

TEST_CASE("the consumer thread changes the output mask between the producer's pushes") {
    // set_output_mask is [any thread]. The producer pushes half the walk, waits until the
    // consumer has turned steps off, then pushes the rest: every step of the first half
    // arrives, none of the second, and positions throughout.
    Engine e(make_config({{"step_detector", "org.pednav.test.counting_steps", {{"every_n", 2}}},
                          {"position_filter", "org.pednav.test.step_counter"}}),
             {fixture_dir("good")}, 65536);
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    REQUIRE(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_STEP) | PN_REC_MASK(PN_REC_POSITION)) == PN_OK);
    constexpr size_t kSamples = 20000, kHalf = kSamples / 2;
    const auto samples = walk(0, kSamples);
    std::atomic<bool> half_pushed{false}, steps_off{false}, done{false};
    std::thread producer([&] {
        for (size_t i = 0; i < kHalf; i += 50) pn_engine_push_imu(e.get(), &samples[i], 50, sizeof(pn_imu_t), nullptr);
        half_pushed = true;
        while (!steps_off.load()) std::this_thread::yield();
        for (size_t i = kHalf; i < kSamples; i += 50) pn_engine_push_imu(e.get(), &samples[i], 50, sizeof(pn_imu_t), nullptr);
        pn_engine_flush(e.get(), nullptr);
        done = true;
    });
    size_t steps = 0, positions = 0;
    pn_output_t o;
    for (;;) {
        const bool finished = done.load();
        while (pn_engine_poll(e.get(), &o) == PN_OK) {
            steps += o.header.type == PN_REC_STEP;
            positions += o.header.type == PN_REC_POSITION;
        }
        if (half_pushed.load() && !steps_off.load()) {
            CHECK(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_POSITION)) == PN_OK);
            steps_off = true;
        }
        if (finished) break;
        std::this_thread::yield();
    }
    producer.join();
    CHECK(positions == kSamples / 2);
    // Samples 0 .. kHalf-2 were processed before the change (the newest waits for the next
    // push): steps at counts 2, 4, ..., kHalf - 2.
    CHECK(steps == kHalf / 2 - 1);
}
