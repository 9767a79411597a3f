// SPDX-License-Identifier: Apache-2.0
// TimeJoin: the records of one sample time handed over together, in every
// order of arrival, with a stream missing, at flush, and when records come
// late or twice.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <pednav_sdk/time_join.hpp>

using pednav::sdk::make_record;
using pednav::sdk::TimeJoin;

namespace {

using Join = TimeJoin<pn_imu_t, pn_gait_phase_t, pn_attitude_t>;

// What a released sample held: its time and, per type, the value that
// identifies the record (-1 when absent).
struct Seen {
    int64_t t_ns;
    double accel_x = -1, statistic = -1, heading = -1;
    bool complete;
};

struct Recorder {
    std::vector<Seen> seen;
    auto on_sample() {
        return [this](const Join::Sample& s) {
            Seen x{s.t_ns(), -1, -1, -1, s.complete()};
            if (const auto* imu = s.get<pn_imu_t>()) x.accel_x = imu->accel_mps2[0];
            if (const auto* g = s.get<pn_gait_phase_t>()) x.statistic = g->statistic;
            if (const auto* a = s.get<pn_attitude_t>()) x.heading = a->heading_rad;
            seen.push_back(x);
        };
    }
};

pn_imu_t imu(int64_t t, double accel_x) {
    auto r = make_record<pn_imu_t>(t);
    r.accel_mps2[0] = accel_x;
    return r;
}
pn_gait_phase_t gait(int64_t t, double statistic) {
    auto r = make_record<pn_gait_phase_t>(t);
    r.stance = 1;
    r.statistic = statistic;
    return r;
}
pn_attitude_t attitude(int64_t t, double heading) {
    auto r = make_record<pn_attitude_t>(t);
    r.q_enu_from_body[0] = 1.0;
    r.heading_rad = heading;
    return r;
}

}  // namespace

TEST_CASE("the joined types as a consumes mask") {
    CHECK(Join::kRecordMask ==
          (PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_GAIT_PHASE) | PN_REC_MASK(PN_REC_ATTITUDE)));
    CHECK(TimeJoin<pn_baro_t>::kRecordMask == PN_REC_MASK(PN_REC_BARO));
    CHECK(Join::index_of<pn_gait_phase_t>() == 1);
}

TEST_CASE("a sample is released by the record that completes it, in any order of arrival") {
    // 0 = IMU, 1 = gait phase, 2 = attitude; the scheduler's order is 0, 1, 2.
    std::array<int, 3> order = {0, 1, 2};
    int orders = 0;
    do {
        CAPTURE(order[0] * 100 + order[1] * 10 + order[2]);
        Join join;
        Recorder r;
        const int64_t t = 5000000;
        for (int k = 0; k < 3; ++k) {
            CHECK(r.seen.empty());
            if (order[k] == 0) join.add(imu(t, 9.5), r.on_sample());
            if (order[k] == 1) join.add(gait(t, 0.25), r.on_sample());
            if (order[k] == 2) join.add(attitude(t, 1.5), r.on_sample());
        }
        REQUIRE(r.seen.size() == 1);  // from the third add, not later
        CHECK(r.seen[0].t_ns == t);
        CHECK(r.seen[0].complete);
        CHECK(r.seen[0].accel_x == 9.5);
        CHECK(r.seen[0].statistic == 0.25);
        CHECK(r.seen[0].heading == 1.5);
        CHECK_FALSE(join.pending());
        join.flush(r.on_sample());
        CHECK(r.seen.size() == 1);  // nothing left for the flush
        ++orders;
    } while (std::next_permutation(order.begin(), order.end()));
    CHECK(orders == 6);
}

TEST_CASE("attitude before and after the gait phase over a stream of samples") {
    Join join;
    Recorder r;
    // Sample 1: attitude before the gait phase; sample 2: after it.
    join.add(imu(1, 1.0), r.on_sample());
    join.add(attitude(1, 0.1), r.on_sample());
    CHECK(r.seen.empty());
    CHECK(join.pending());
    CHECK(join.pending_t_ns() == 1);
    join.add(gait(1, 0.01), r.on_sample());
    REQUIRE(r.seen.size() == 1);
    join.add(imu(2, 2.0), r.on_sample());
    join.add(gait(2, 0.02), r.on_sample());
    CHECK(r.seen.size() == 1);
    join.add(attitude(2, 0.2), r.on_sample());
    REQUIRE(r.seen.size() == 2);
    CHECK(r.seen[0].t_ns == 1);
    CHECK(r.seen[0].heading == 0.1);
    CHECK(r.seen[0].statistic == 0.01);
    CHECK(r.seen[1].t_ns == 2);
    CHECK(r.seen[1].accel_x == 2.0);
    CHECK(r.seen[1].statistic == 0.02);
    CHECK(r.seen[1].complete);
}

TEST_CASE(
    "without a gait phase stream a sample is released by the next sample's first record, the last at flush") {
    Join join;
    Recorder r;
    for (int64_t t = 1; t <= 3; ++t) {
        join.add(imu(t, 10.0 * t), r.on_sample());
        // Sample t - 1 went out when IMU(t) arrived, before IMU(t) was taken in.
        CHECK(r.seen.size() == static_cast<size_t>(t - 1));
        join.add(attitude(t, 0.5 * t), r.on_sample());
    }
    CHECK(r.seen.size() == 2);
    join.flush(r.on_sample());
    REQUIRE(r.seen.size() == 3);
    for (int64_t t = 1; t <= 3; ++t) {
        const Seen& s = r.seen[t - 1];
        CHECK(s.t_ns == t);
        CHECK(s.accel_x == 10.0 * t);
        CHECK(s.heading == 0.5 * t);
        CHECK(s.statistic == -1);  // absent
        CHECK_FALSE(s.complete);
    }
    join.flush(r.on_sample());
    CHECK(r.seen.size() == 3);
}

TEST_CASE("a sample without an attitude (the estimator still aligning) is released with what it has") {
    Join join;
    Recorder r;
    join.add(imu(1, 1.0), r.on_sample());
    join.add(gait(1, 0.3), r.on_sample());
    join.add(imu(2, 2.0), r.on_sample());  // no attitude for sample 1
    REQUIRE(r.seen.size() == 1);
    CHECK(r.seen[0].t_ns == 1);
    CHECK(r.seen[0].accel_x == 1.0);
    CHECK(r.seen[0].statistic == 0.3);
    CHECK(r.seen[0].heading == -1);
    // A gait phase of a later time also releases the pending sample.
    join.add(gait(3, 0.4), r.on_sample());
    REQUIRE(r.seen.size() == 2);
    CHECK(r.seen[1].t_ns == 2);
    CHECK(r.seen[1].statistic == -1);
}

TEST_CASE("a second record of a type already held releases the first; late records are dropped and counted") {
    Join join;
    Recorder r;
    join.add(imu(10, 1.0), r.on_sample());
    join.add(attitude(10, 0.1), r.on_sample());
    join.add(attitude(10, 0.2), r.on_sample());  // the same time again
    REQUIRE(r.seen.size() == 1);
    CHECK(r.seen[0].heading == 0.1);
    CHECK(r.seen[0].accel_x == 1.0);
    CHECK(join.pending_t_ns() == 10);
    join.add(gait(9, 0.5), r.on_sample());  // older than the pending sample
    join.add(imu(11, 2.0), r.on_sample());
    REQUIRE(r.seen.size() == 2);
    CHECK(r.seen[1].heading == 0.2);
    CHECK(r.seen[1].accel_x == -1);  // the second attitude's sample had no IMU record
    CHECK(r.seen[1].statistic == -1);
    join.add(gait(11, 0.6), r.on_sample());
    join.add(attitude(11, 0.3), r.on_sample());
    REQUIRE(r.seen.size() == 3);
    join.add(imu(10, 3.0), r.on_sample());  // older than the last released sample
    CHECK_FALSE(join.pending());
    CHECK(join.late_records() == 2);
    join.flush(r.on_sample());
    CHECK(r.seen.size() == 3);
}

TEST_CASE("held records are copies; the completing record is handed over in place") {
    Join join;
    const pn_attitude_t* handed = nullptr;
    double accel_x = 0;
    pn_imu_t sample_imu = imu(1, 4.0);
    join.add(sample_imu, [](const Join::Sample&) {});
    sample_imu.accel_mps2[0] = -4.0;  // the caller's record changes after add()
    join.add(gait(1, 0.1), [](const Join::Sample&) {});
    const pn_attitude_t att = attitude(1, 0.7);
    join.add(att, [&](const Join::Sample& s) {
        handed = s.get<pn_attitude_t>();
        accel_x = s.get<pn_imu_t>()->accel_mps2[0];
    });
    CHECK(handed == &att);
    CHECK(accel_x == 4.0);
}

TEST_CASE("a sample whose handler throws is consumed, and the record that released it dropped") {
    Join join;
    int calls = 0;
    const auto throwing = [&](const Join::Sample&) {
        ++calls;
        throw std::runtime_error("diverged");
    };
    join.add(imu(1, 1.0), throwing);
    join.add(attitude(1, 0.1), throwing);
    CHECK_THROWS_AS(join.add(imu(2, 2.0), throwing), std::runtime_error);
    CHECK(calls == 1);
    CHECK_FALSE(join.pending());  // IMU(2) was dropped with the exception
    Recorder r;
    join.add(attitude(2, 0.2), r.on_sample());
    join.flush(r.on_sample());
    REQUIRE(r.seen.size() == 1);
    CHECK(r.seen[0].t_ns == 2);
    CHECK(r.seen[0].accel_x == -1);
    CHECK(r.seen[0].heading == 0.2);
}

TEST_CASE("a join of one type releases every record at once; clear() drops a pending sample") {
    TimeJoin<pn_baro_t> baro;
    std::vector<int64_t> times;
    for (int64_t t : {1, 2, 2, 5}) {
        auto b = make_record<pn_baro_t>(t);
        baro.add(b, [&](const TimeJoin<pn_baro_t>::Sample& s) {
            CHECK(s.complete());
            times.push_back(s.t_ns());
        });
    }
    CHECK(times == std::vector<int64_t>{1, 2, 2, 5});
    Join join;
    Recorder r;
    join.add(imu(1, 1.0), r.on_sample());
    join.clear();
    join.flush(r.on_sample());
    CHECK(r.seen.empty());
}
