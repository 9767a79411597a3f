// SPDX-License-Identifier: Apache-2.0
// Pushing samples and polling outputs through the C API: input validation,
// strides, determinism, look-ahead alignment, feedback, flush and reset.
#include <doctest/doctest.h>

#include "same_bytes.hpp"
#include "test_support.hpp"

using namespace pednav::test;

namespace {

// Step detector (a step every 10 samples, optional look-ahead) followed by
// the fixed-stride position filter.
std::string steps_config(int latency_samples = 0, bool check_alignment = false, bool declare_latency = true) {
    return make_config(
        {{"step_detector",
          "org.pednav.test.counting_steps",
          {{"latency_samples", latency_samples}, {"declare_latency", declare_latency}}},
         {"position_filter", "org.pednav.test.step_counter", {{"check_alignment", check_alignment}}}});
}

std::string full_config(int latency_samples, double correction_rad) {
    return make_config(
        {{"step_detector", "org.pednav.test.counting_steps", {{"latency_samples", latency_samples}}},
         {"attitude_estimator", "org.pednav.test.fixed_heading", {{"heading_deg", 0.0}}},
         {"position_filter",
          "org.pednav.test.step_counter",
          {{"check_alignment", true}, {"correction_rad", correction_rad}}}});
}

}  // namespace

TEST_CASE("version and status names") {
    CHECK(pn_abi_version() == PN_ABI_VERSION);
    CHECK(std::string(pn_version_string()).size() > 0);
    CHECK(std::string(pn_status_name(PN_E_NUMERIC)) == "PN_E_NUMERIC");
    CHECK(std::string(pn_status_name(PN_NO_DATA)) == "PN_NO_DATA");
    CHECK(pn_status_name(-1000) != nullptr);
}

TEST_CASE("a fixed-stride walk gives one step, stride and position every 10 samples") {
    Engine e(steps_config(), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    REQUIRE(push(e, walk(0, 100)) == PN_OK);
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
    const auto out = e.poll_all();
    const auto steps = of_type(out, PN_REC_STEP), strides = of_type(out, PN_REC_STRIDE),
               pos = of_type(out, PN_REC_POSITION);
    REQUIRE(steps.size() == 10);
    REQUIRE(strides.size() == 10);
    REQUIRE(pos.size() == 10);
    double north = 0.0;
    for (size_t i = 0; i < 10; ++i) {
        north += 0.7;
        CHECK(steps[i].header.t_ns == sample_t_ns(10 * i + 9));
        CHECK(strides[i].stride.index == static_cast<int32_t>(i));
        CHECK(pos[i].position.pos_enu_m[0] == 0.0);  // heading 0: due north
        CHECK(pos[i].position.pos_enu_m[1] == north);
        CHECK(pos[i].position.cov_enu_m2[0] == doctest::Approx(0.01 * static_cast<double>(i + 1)));
        CHECK(pos[i].header.source_id != 0);  // produced by a stage, not the app
    }
    // The engine counts what it took in.
    CHECK(e.describe()["counters"]["records_in"] == 100);
}

TEST_CASE("push_imu honours a stride larger than sizeof(pn_imu_t)") {
    // An app keeping extra per-sample data next to each record, and one
    // built against a newer minor whose IMU record is longer.
    struct Padded {
        pn_imu_t imu;
        double app_data[5];
    };
    struct Longer {
        pn_imu_t imu;
        double future_field[2];
    };
    const auto plain = walk(0, 100);
    std::vector<Padded> padded(plain.size());
    std::vector<Longer> longer(plain.size());
    for (size_t i = 0; i < plain.size(); ++i) {
        padded[i].imu = plain[i];
        for (double& x : padded[i].app_data) x = std::nan("");  // must never be read as a sample
        longer[i].imu = plain[i];
        longer[i].imu.header.struct_size = sizeof(Longer);
        longer[i].future_field[0] = longer[i].future_field[1] = 1e300;
    }
    Engine a(steps_config(), {fixture_dir("good")}), b(steps_config(), {fixture_dir("good")}),
        c(steps_config(), {fixture_dir("good")});
    REQUIRE(push(a, plain) == PN_OK);
    pn_error_t err = make_error();
    REQUIRE(pn_engine_push_imu(b.get(), &padded[0].imu, padded.size(), sizeof(Padded), &err) == PN_OK);
    REQUIRE(pn_engine_push_imu(c.get(), &longer[0].imu, longer.size(), sizeof(Longer), &err) == PN_OK);
    for (auto* e : {&a, &b, &c}) REQUIRE(pn_engine_flush(e->get(), nullptr) == PN_OK);
    const auto oa = a.poll_all();
    CHECK(oa.size() == 30);
    CHECK(same_bytes(oa, b.poll_all()));
    CHECK(same_bytes(oa, c.poll_all()));
    // A stride shorter than the record is an argument error.
    Engine d(steps_config(), {fixture_dir("good")});
    CHECK(pn_engine_push_imu(d.get(), plain.data(), plain.size(), sizeof(pn_imu_t) - 8, nullptr) ==
          PN_E_INVALID_ARGUMENT);
    CHECK(pn_engine_push_imu(d.get(), plain.data(), plain.size(), 8, nullptr) == PN_E_INVALID_ARGUMENT);
    CHECK(d.describe()["counters"]["records_in"] == 0);
}

TEST_CASE("push_imu refuses a later sample whose struct_size exceeds the stride") {
    // The engine copies struct_size bytes of each sample: a sample claiming
    // more than the stride would make it read past the app's array.
    auto samples = walk(0, 30);
    samples[12].header.struct_size = sizeof(pn_imu_t) + 64;
    Engine e(steps_config(), {fixture_dir("good")});
    pn_error_t err = make_error();
    CHECK(push(e, samples, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(err.detail == 12);
    CHECK_MESSAGE(contains(err.message, "sample 12"), err.message);
    CHECK_MESSAGE(contains(err.message, "stride_bytes"), err.message);
    CHECK(e.describe()["counters"]["records_in"] == 12);  // the samples before it went in
}

TEST_CASE("a NaN input sample is rejected with err.detail = its index; the samples before it are kept") {
    Engine e(steps_config(), {fixture_dir("good")});
    auto samples = walk(0, 30);
    samples[17].gyro_radps[1] = std::nan("");
    pn_error_t err = make_error();
    CHECK(push(e, samples, &err) == PN_E_NUMERIC);
    CHECK(err.code == PN_E_NUMERIC);
    CHECK(err.detail == 17);
    // The first 17 samples went in: the step at sample 10 (index 9) is out.
    CHECK(of_type(e.poll_all(), PN_REC_STEP).size() == 1);
    // The stream continues after the bad sample.
    const std::vector<pn_imu_t> rest(samples.begin() + 18, samples.end());
    CHECK(push(e, rest) == PN_OK);
    CHECK(e.describe()["counters"]["records_in"] == 29);
}

TEST_CASE("time going backwards or repeating is rejected with err.detail = the index") {
    Engine e(steps_config(), {fixture_dir("good")});
    auto samples = walk(0, 20);
    SUBCASE("backwards") { samples[5].header.t_ns = samples[3].header.t_ns; }
    SUBCASE("repeated") { samples[5].header.t_ns = samples[4].header.t_ns; }
    pn_error_t err = make_error();
    CHECK(push(e, samples, &err) == PN_E_OUT_OF_ORDER);
    CHECK(err.detail == 5);
    CHECK(e.describe()["counters"]["records_in"] == 5);
}

TEST_CASE("a time beyond the engine's clock range (+-2^62 ns) is refused; the stream goes on") {
    Engine e(steps_config(), {fixture_dir("good")});
    auto samples = walk(0, 20);
    pn_error_t err = make_error();
    pn_imu_t far = samples[0];
    far.header.t_ns = INT64_MIN + 10000000000;  // a clock near the lowest int64 (found by fuzz_push_records)
    CHECK(pn_engine_push(e.get(), &far.header, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(std::string(err.message).find("outside the engine's clock range") != std::string::npos);
    far.header.t_ns = (int64_t{1} << 62) + 1;
    CHECK(pn_engine_push(e.get(), &far.header, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(push(e, samples) == PN_OK);
    CHECK(e.describe()["counters"]["records_in"] == 20);
}

TEST_CASE("determinism: the same input gives bit-identical output however it is batched") {
    const std::string config = full_config(3, 0.01);
    Engine a(config, {fixture_dir("good")}), b(config, {fixture_dir("good")});
    REQUIRE(a.status() == PN_OK);
    REQUIRE(b.status() == PN_OK);
    for (auto* e : {&a, &b})
        REQUIRE(
            pn_engine_set_output_mask(e->get(), PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) |
                                                    PN_REC_MASK(PN_REC_STEP) | PN_REC_MASK(PN_REC_ATTITUDE) |
                                                    PN_REC_MASK(PN_REC_GAIT_PHASE)) == PN_OK);
    const auto samples = walk(0, 500);
    REQUIRE(push(a, samples) == PN_OK);
    const size_t batches[] = {1, 7, 13, 2, 31, 64, 3};
    size_t i = 0, j = 0;
    while (i < samples.size()) {
        const size_t n = std::min(batches[j++ % 7], samples.size() - i);
        REQUIRE(pn_engine_push_imu(b.get(), &samples[i], n, sizeof(pn_imu_t), nullptr) == PN_OK);
        i += n;
    }
    REQUIRE(pn_engine_flush(a.get(), nullptr) == PN_OK);
    REQUIRE(pn_engine_flush(b.get(), nullptr) == PN_OK);
    const auto oa = a.poll_all(), ob = b.poll_all();
    CHECK(oa.size() == 50 * 3 + 500 * 2);  // step+stride+position per step, attitude+gait per sample
    CHECK(same_bytes(oa, ob));
}

TEST_CASE("look-ahead: latency is reported, flush drains it, downstream sees decisions aligned") {
    Engine e(steps_config(5, true), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    CHECK(pn_engine_latency_ns(e.get()) == 5 * kDtNs);
    CHECK(e.describe()["pipeline"]["latency_ns"] == 5 * kDtNs);
    pn_error_t err = make_error();
    REQUIRE_MESSAGE(push(e, walk(0, 100), &err) == PN_OK, err.message);
    // The step at sample 100 is still inside the detector's look-ahead.
    auto before = of_type(e.poll_all(), PN_REC_STEP);
    CHECK(before.size() == 9);
    REQUIRE_MESSAGE(pn_engine_flush(e.get(), &err) == PN_OK, err.message);
    const auto after = e.poll_all();
    const auto steps = of_type(after, PN_REC_STEP);
    REQUIRE(steps.size() == 1);
    CHECK(steps[0].header.t_ns == sample_t_ns(99));
    // The position filter (check_alignment) refused nothing: it saw every
    // GAIT_PHASE(t) and STEP(t) right after IMU(t), and moved on the last step.
    const auto pos = of_type(after, PN_REC_POSITION);
    REQUIRE(pos.size() == 1);
    CHECK(pos[0].position.pos_enu_m[1] == doctest::Approx(7.0));
    // Pushing after flush starts a new segment.
    CHECK(push(e, walk(100, 20)) == PN_OK);
}

TEST_CASE("look-ahead control: undeclared latency misaligns downstream and the fixture's check fails") {
    Engine e(steps_config(5, true, false), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    CHECK(pn_engine_latency_ns(e.get()) == 0);
    pn_error_t err = make_error();
    CHECK(push(e, walk(0, 20), &err) == PN_E_BAD_INPUT);
    CHECK(std::string(err.where) == "foot/position_filter");
    CHECK_MESSAGE(contains(err.message, "arrived after IMU"), err.message);
}

TEST_CASE("feedback: a correction emitted at sample k applies from sample k+1") {
    for (int latency : {0, 4}) {
        CAPTURE(latency);
        Engine e(full_config(latency, 0.1), {fixture_dir("good")});
        REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
        const auto d = e.describe();
        REQUIRE(d["pipeline"]["feedback"].size() == 1);
        CHECK(d["pipeline"]["feedback"][0]["from"] == "foot/position_filter");
        CHECK(d["pipeline"]["feedback"][0]["to"] == "foot/attitude_estimator");
        REQUIRE(pn_engine_set_output_mask(
                    e.get(), PN_REC_MASK(PN_REC_ATTITUDE) | PN_REC_MASK(PN_REC_POSITION)) == PN_OK);
        pn_error_t err = make_error();
        REQUIRE_MESSAGE(push(e, walk(0, 40), &err) == PN_OK, err.message);
        REQUIRE(pn_engine_flush(e.get(), &err) == PN_OK);
        const auto out = e.poll_all();
        const auto att = of_type(out, PN_REC_ATTITUDE);
        REQUIRE(att.size() == 40);
        // Steps at samples 10, 20, 30 (indices 9, 19, 29) each turn by 0.1 rad.
        CHECK(att[9].attitude.heading_rad == 0.0);
        CHECK(att[10].attitude.heading_rad == doctest::Approx(-0.1));
        CHECK(att[19].attitude.heading_rad == doctest::Approx(-0.1));
        CHECK(att[20].attitude.heading_rad == doctest::Approx(-0.2));
        CHECK(att[39].attitude.heading_rad == doctest::Approx(-0.3));
        // The second step walks along the corrected heading.
        const auto pos = of_type(out, PN_REC_POSITION);
        REQUIRE(pos.size() == 4);
        CHECK(pos[1].position.pos_enu_m[0] == doctest::Approx(0.7 * std::sin(-0.1)));
    }
}

TEST_CASE("feedback released by flush arrives a round late: a correction about sample k applies from k+2") {
    // The step detector's look-ahead of 4 samples holds samples 28-31 until the flush, which
    // releases them at once; the step at sample 30 (index 29) is among them.
    Engine e(full_config(4, 0.1), {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    REQUIRE(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_ATTITUDE)) == PN_OK);
    pn_error_t err = make_error();
    REQUIRE_MESSAGE(push(e, walk(0, 32), &err) == PN_OK, err.message);
    REQUIRE(pn_engine_flush(e.get(), &err) == PN_OK);
    const auto att = of_type(e.poll_all(), PN_REC_ATTITUDE);
    REQUIRE(att.size() == 32);
    CHECK(att[20].attitude.heading_rad == doctest::Approx(-0.2));  // pushed one by one: from k+1
    CHECK(att[30].attitude.heading_rad == doctest::Approx(-0.2));  // released by flush: not yet
    CHECK(att[31].attitude.heading_rad == doctest::Approx(-0.3));
}

TEST_CASE("reset empties the queues and replays identically from the start") {
    Engine e(steps_config(2), {fixture_dir("good")});
    REQUIRE(push(e, walk(0, 60)) == PN_OK);
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
    const auto first = e.poll_all();
    REQUIRE(push(e, walk(60, 10)) == PN_OK);
    REQUIRE(pn_engine_reset(e.get(), nullptr) == PN_OK);
    pn_output_t o;
    CHECK(pn_engine_poll(e.get(), &o) == PN_NO_DATA);
    CHECK(pn_engine_get_latest(e.get(), PN_REC_POSITION, &o) == PN_NO_DATA);
    REQUIRE(push(e, walk(0, 60)) == PN_OK);  // time starts over
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
    CHECK(same_bytes(first, e.poll_all()));
}

TEST_CASE("output mask, get_latest and a full output queue") {
    Engine e(steps_config(), {fixture_dir("good")}, 4);
    REQUIRE(pn_engine_set_output_mask(e.get(), PN_REC_MASK(PN_REC_POSITION)) == PN_OK);
    REQUIRE(push(e, walk(0, 100)) == PN_OK);
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
    // 10 positions, room for 4: the newest 6 are dropped and counted ...
    CHECK(e.describe()["counters"]["outputs_dropped"] == 6);
    // ... and said at the 1st, 2nd and 4th drop, not once per record.
    const auto warnings = e.describe()["warnings"];
    size_t full = 0;
    for (const auto& w : warnings)
        if (w.get<std::string>().find("the output queue is full (4 records)") != std::string::npos) ++full;
    CHECK(full == 3);
    // ... but get_latest still sees the newest.
    pn_output_t latest;
    REQUIRE(pn_engine_get_latest(e.get(), PN_REC_POSITION, &latest) == PN_OK);
    CHECK(latest.header.t_ns == sample_t_ns(99));
    CHECK(latest.position.pos_enu_m[1] == doctest::Approx(7.0));
    CHECK(pn_engine_get_latest(e.get(), PN_REC_STEP, &latest) == PN_NO_DATA);
    const auto out = e.poll_all();
    REQUIRE(out.size() == 4);
    for (const auto& o : out) CHECK(o.header.type == PN_REC_POSITION);
}

TEST_CASE("set_start moves the track; the map matcher adds the floor from the barometer") {
    Engine e(make_config({{"step_detector", "org.pednav.test.counting_steps"},
                          {"position_filter", "org.pednav.test.step_counter"},
                          {"map_matcher", "org.pednav.test.floor_from_baro"}}),
             {fixture_dir("good")});
    REQUIRE_MESSAGE(e.status() == PN_OK, e.error().message);
    const double start[3] = {10.0, 20.0, 0.0};
    REQUIRE(pn_engine_set_start(e.get(), start, 90.0, nullptr) == PN_OK);  // facing east
    for (size_t k = 0; k < 50; ++k) {
        const pn_imu_t s = imu_sample(k);
        REQUIRE(pn_engine_push(e.get(), &s.header, nullptr) == PN_OK);
        if (k % 5 == 0) {  // 20 Hz barometer climbing one 3 m floor (36 Pa) by sample 25
            pn_baro_t b;
            std::memset(&b, 0, sizeof b);
            b.header.struct_size = sizeof b;
            b.header.type = PN_REC_BARO;
            b.header.t_ns = s.header.t_ns;
            b.pressure_pa = 101325.0 - (k >= 25 ? 36.0 : 0.0);
            b.temperature_c = 20.0;
            REQUIRE(pn_engine_push(e.get(), &b.header, nullptr) == PN_OK);
        }
    }
    REQUIRE(pn_engine_flush(e.get(), nullptr) == PN_OK);
    const auto pos = of_type(e.poll_all(), PN_REC_POSITION);
    REQUIRE(pos.size() == 5);  // only the map matcher's positions reach the app
    CHECK(pos[0].position.pos_enu_m[0] == doctest::Approx(10.7));
    CHECK(pos[0].position.pos_enu_m[1] == doctest::Approx(20.0));
    CHECK(pos[0].position.source == PN_POSITION_SOURCE_MAP);
    CHECK((pos[0].position.header.flags & PN_POSITION_FLAG_HAS_FLOOR) != 0);
    CHECK(pos[0].position.floor == 0);
    CHECK(pos[4].position.floor == 1);
}

TEST_CASE("push refuses records that are not inputs or are malformed") {
    Engine e(steps_config(), {fixture_dir("good")});
    pn_error_t err = make_error();
    pn_position_t p;
    std::memset(&p, 0, sizeof p);
    p.header.struct_size = sizeof p;
    p.header.type = PN_REC_POSITION;
    p.header.t_ns = kT0Ns;
    CHECK(pn_engine_push(e.get(), &p.header, &err) == PN_E_INVALID_ARGUMENT);
    // Unknown ids, including ones past the 64 mask bits (65 would alias IMU's bit).
    for (uint32_t type : {0u, 11u, 63u, 64u, 65u, 200u}) {
        CAPTURE(type);
        pn_imu_t odd = imu_sample(0);
        odd.header.type = type;
        err = make_error();
        CHECK(pn_engine_push(e.get(), &odd.header, &err) == PN_E_INVALID_ARGUMENT);
        CHECK_MESSAGE(contains(err.message, "not an input type"), err.message);
    }
    pn_imu_t s = imu_sample(0);
    s.header.struct_size = sizeof(pn_record_header_t);  // truncated
    CHECK(pn_engine_push(e.get(), &s.header, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(pn_engine_push(e.get(), nullptr, &err) == PN_E_INVALID_ARGUMENT);
    CHECK(pn_engine_push_imu(nullptr, &s, 1, sizeof s, nullptr) == PN_E_INVALID_ARGUMENT);
    CHECK(e.describe()["counters"]["records_in"] == 0);
    // A good sample still goes in afterwards.
    s = imu_sample(0);
    CHECK(pn_engine_push(e.get(), &s.header, &err) == PN_OK);
}
