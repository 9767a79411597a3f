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
