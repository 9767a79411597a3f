// SPDX-License-Identifier: Apache-2.0
// pn_engine.h threading contract: one thread may push while one other thread
// polls. Every output arrives exactly once and in order. Engines in different
// threads share nothing: eight at once give, bit for bit, what each gives
// alone. Labelled `threads` in ctest (ctest -L threads), for the TSan build.
#include <algorithm>
#include <atomic>
#include <fstream>
#include <sstream>
#include <thread>

#include <doctest/doctest.h>

#include "same_bytes.hpp"
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

namespace {

std::string preset(const std::string& mount) {
    std::ifstream in(std::string(PEDNAV_CONFIG_DIR) + "/" + mount + ".json");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Input number `n`: 60 s of a walk at 100 Hz whose cadence, bounce and turn
// rate depend on n, so no two engines see the same samples.
std::vector<pn_imu_t> varied_walk(int n) {
    std::vector<pn_imu_t> v;
    const double cadence_hz = 1.6 + 0.1 * n, bounce = 1.0 + 0.15 * n, yaw_radps = 0.02 * (n - 4);
    for (size_t k = 0; k < 6000; ++k) {
        pn_imu_t s = imu_sample(k);
        const double t = static_cast<double>(k) * 0.01, phase = 2 * 3.14159265358979323846 * cadence_hz * t;
        s.accel_mps2[0] = 0.4 * std::sin(phase);
        s.accel_mps2[2] = 9.81 + bounce * std::cos(phase) + 0.3 * std::cos(2 * phase);
        s.gyro_radps[0] = 0.5 * std::sin(phase);
        s.gyro_radps[2] = yaw_radps;
        v.push_back(s);
    }
    return v;
}

struct Run {
    pn_status_t status = PN_E_INTERNAL;
    std::string error;
    std::vector<pn_output_t> outputs;
};

// Creates an engine for `mount`, pushes `input` in batches of 64, flushes and polls everything.
Run run_engine(const std::string& mount, const std::vector<pn_imu_t>& input) {
    Run r;
    Engine e(preset(mount), {PEDNAV_PLUGIN_OUTPUT_DIR}, 65536);
    r.status = e.status();
    r.error = e.error().message;
    if (r.status != PN_OK) return r;
    pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STEP) |
                                           PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_ATTITUDE));
    for (size_t i = 0; i < input.size() && r.status == PN_OK; i += 64) {
        r.status = pn_engine_push_imu(e.get(), &input[i], std::min<size_t>(64, input.size() - i), sizeof(pn_imu_t), nullptr);
        for (const auto& o : e.poll_all()) r.outputs.push_back(o);
    }
    if (r.status == PN_OK) r.status = pn_engine_flush(e.get(), nullptr);
    for (const auto& o : e.poll_all()) r.outputs.push_back(o);
    return r;
}

}  // namespace

TEST_CASE("eight engines in eight threads over different inputs give, bit for bit, the serial results") {
    const char* const mounts[] = {"foot", "chest", "handheld", "waist"};
    constexpr int kEngines = 8;
    std::vector<std::vector<pn_imu_t>> inputs;
    for (int n = 0; n < kEngines; ++n) inputs.push_back(varied_walk(n));

    std::vector<Run> serial;
    for (int n = 0; n < kEngines; ++n) serial.push_back(run_engine(mounts[n % 4], inputs[n]));
    for (int n = 0; n < kEngines; ++n) {
        CAPTURE(n);
        REQUIRE_MESSAGE(serial[n].status == PN_OK, serial[n].error);
        CHECK(of_type(serial[n].outputs, PN_REC_POSITION).size() > 100);
    }
    for (int n = 0; n + 4 < kEngines; ++n) CHECK_FALSE(same_bytes(serial[n].outputs, serial[n + 4].outputs));

    std::vector<Run> threaded(kEngines);
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (int n = 0; n < kEngines; ++n)
        threads.emplace_back([&, n] {
            ++ready;
            while (ready.load() < kEngines) std::this_thread::yield();  // start together: loading overlaps too
            threaded[n] = run_engine(mounts[n % 4], inputs[n]);
        });
    for (auto& t : threads) t.join();
    for (int n = 0; n < kEngines; ++n) {
        CAPTURE(n);
        CAPTURE(mounts[n % 4]);
        REQUIRE_MESSAGE(threaded[n].status == PN_OK, threaded[n].error);
        CHECK(threaded[n].outputs.size() == serial[n].outputs.size());
        CHECK(same_bytes(threaded[n].outputs, serial[n].outputs));
    }
}
