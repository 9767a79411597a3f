// SPDX-License-Identifier: Apache-2.0
// White-box tests of the engine's record value checks (record_checks.hpp):
// the verdict and the reason come from one checker, so a refused record
// always says why.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "record_checks.hpp"

using namespace pednav::engine;

namespace {

template <typename T>
T record(pn_record_type_t type) {
    T r;
    std::memset(&r, 0, sizeof r);
    r.header.struct_size = sizeof r;
    r.header.type = type;
    return r;
}

pn_attitude_t attitude_of_norm(double norm) {
    auto a = record<pn_attitude_t>(PN_REC_ATTITUDE);
    a.q_enu_from_body[0] = norm * 0.6;
    a.q_enu_from_body[3] = norm * 0.8;
    return a;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a quaternion is refused exactly when its norm is off by more than the tolerance, with a reason") {
    static_assert(kUnitQuaternionTolerance == 1e-3);
    for (double off : {0.0, 0.5e-3, 0.97e-3, -0.97e-3}) {
        CAPTURE(off);
        const auto a = attitude_of_norm(1 + off);
        CHECK(record_values_ok(&a.header));
        CHECK(describe(find_value_problem(&a.header)).empty());
    }
    for (double off : {1.03e-3, -1.03e-3, 0.1, -1.0}) {
        CAPTURE(off);
        const auto a = attitude_of_norm(1 + off);
        CHECK(!record_values_ok(&a.header));
        const ValueProblem p = find_value_problem(&a.header);
        REQUIRE(p);
        CHECK(std::string(p.field) == "q_enu_from_body");
        CHECK(p.value == doctest::Approx(1 + off));
        const std::string why = describe(p);
        CHECK_MESSAGE(contains(why, "q_enu_from_body"), why);
        CHECK_MESSAGE(contains(why, "not a unit quaternion"), why);
    }
}

TEST_CASE("every refused record names the field, the element and the value") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    SUBCASE("imu") {
        auto r = record<pn_imu_t>(PN_REC_IMU);
        CHECK(record_values_ok(&r.header));
        r.gyro_radps[2] = nan;
        CHECK(!record_values_ok(&r.header));
        CHECK(describe(find_value_problem(&r.header)) == "gyro_radps[2] is nan");
    }
    SUBCASE("baro") {
        auto r = record<pn_baro_t>(PN_REC_BARO);
        r.pressure_pa = -3;
        CHECK(!record_values_ok(&r.header));
        CHECK(describe(find_value_problem(&r.header)) == "pressure_pa is -3 (not positive)");
    }
    SUBCASE("gnss") {
        auto r = record<pn_gnss_t>(PN_REC_GNSS);
        CHECK(record_values_ok(&r.header));
        r.lat_deg = 91;
        CHECK(!record_values_ok(&r.header));
        CHECK(contains(describe(find_value_problem(&r.header)), "lat_deg is 91"));
        r.lat_deg = 0;
        r.h_accuracy_m = std::numeric_limits<double>::infinity();
        CHECK(!record_values_ok(&r.header));
        CHECK(describe(find_value_problem(&r.header)) == "h_accuracy_m is inf");
    }
    SUBCASE("step") {
        auto r = record<pn_step_t>(PN_REC_STEP);
        CHECK(record_values_ok(&r.header));
        r.frequency_hz = nan;
        CHECK(!record_values_ok(&r.header));
        CHECK(describe(find_value_problem(&r.header)) == "frequency_hz is nan");
        r.frequency_hz = 1.8;
        r.accel_min_mps2 = nan;  // a 1.1 field
        CHECK(describe(find_value_problem(&r.header)) == "accel_min_mps2 is nan");
        r.header.struct_size = PN_STEP_MIN_SIZE;  // a 1.0 producer: the tail is not its
        CHECK(record_values_ok(&r.header));
    }
    SUBCASE("position covariance") {
        auto r = record<pn_position_t>(PN_REC_POSITION);
        CHECK(record_values_ok(&r.header));
        r.vel_enu_mps[0] = nan;  // ignored without the velocity flag
        CHECK(record_values_ok(&r.header));
        r.cov_enu_m2[8] = -1;
        CHECK(!record_values_ok(&r.header));
        CHECK(describe(find_value_problem(&r.header)) == "cov_enu_m2[8] is -1 (negative variance)");
        r.header.flags = PN_POSITION_FLAG_HAS_VELOCITY;
        CHECK(describe(find_value_problem(&r.header)) == "vel_enu_mps[0] is nan");
    }
}

TEST_CASE("a covariance is refused when it is not symmetric or not positive semi-definite, with the element") {
    auto pos = record<pn_position_t>(PN_REC_POSITION);
    double* c = pos.cov_enu_m2;
    auto verdict = [&] { return describe(find_value_problem(&pos.header)); };
    auto fill = [&](const double (&m)[9]) { std::memcpy(c, m, sizeof m); };

    SUBCASE("valid: diagonal, rank-deficient, and a rotated one with rounding") {
        const double diagonal[9] = {1, 0, 0, 0, 2, 0, 0, 0, 3};
        fill(diagonal);
        CHECK(record_values_ok(&pos.header));
        const double rank_one_block[9] = {1, 1, 0, 1, 1, 0, 0, 0, 1};  // correlation exactly 1: PSD, singular
        fill(rank_one_block);
        CHECK(record_values_ok(&pos.header));
        // R diag(4, 1, 0.25) R^T for a rotation of 0.7 rad about z then 0.3 about x, in doubles.
        const double cz = std::cos(0.7), sz = std::sin(0.7), cx = std::cos(0.3), sx = std::sin(0.3);
        const double R[3][3] = {{cz, -sz * cx, sz * sx}, {sz, cz * cx, -cz * sx}, {0, sx, cx}};
        const double d[3] = {4, 1, 0.25};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                c[3 * i + j] = 0;
                for (int k = 0; k < 3; ++k) c[3 * i + j] += R[i][k] * d[k] * R[j][k];
            }
        CHECK(record_values_ok(&pos.header));
    }
    SUBCASE("a correlation of 2 between east and north") {
        const double m[9] = {1, 2, 0, 2, 1, 0, 0, 0, 1};
        fill(m);
        CHECK_FALSE(record_values_ok(&pos.header));
        CHECK_MESSAGE(contains(verdict(), "cov_enu_m2[1] is 2 (a correlation above 1: not positive semi-definite)"),
                      verdict());
    }
    SUBCASE("every 2x2 minor fine, the determinant negative") {
        // Correlations 0.9, 0.9, -0.9: each pair is possible, the three together are not.
        const double m[9] = {1, 0.9, 0.9, 0.9, 1, -0.9, 0.9, -0.9, 1};
        fill(m);
        CHECK_FALSE(record_values_ok(&pos.header));
        CHECK_MESSAGE(contains(verdict(), "as determinant (not positive semi-definite)"), verdict());
    }
    SUBCASE("[0][1] and [1][0] differ") {
        const double m[9] = {1, 0.5, 0, 0, 1, 0, 0, 0, 1};
        fill(m);
        CHECK_FALSE(record_values_ok(&pos.header));
        CHECK_MESSAGE(contains(verdict(), "cov_enu_m2[1] is 0.5 (not symmetric"), verdict());
    }
    SUBCASE("an asymmetry of rounding size is accepted") {
        const double m[9] = {1, 0.5, 0, 0.5 * (1 + 1e-12), 1, 0, 0, 0, 1};
        fill(m);
        CHECK(record_values_ok(&pos.header));
    }
}

TEST_CASE("values whose sum overflows are still finite: the fast path's doubt goes to the exact check") {
    const double big = std::numeric_limits<double>::max();
    auto imu = record<pn_imu_t>(PN_REC_IMU);
    imu.accel_mps2[0] = big;
    imu.accel_mps2[1] = big;  // the sum overflows to infinity
    CHECK(record_values_ok(&imu.header));
    imu.accel_mps2[2] = -std::numeric_limits<double>::infinity();
    CHECK(!record_values_ok(&imu.header));
    CHECK(describe(find_value_problem(&imu.header)) == "accel_mps2[2] is -inf");
    imu.accel_mps2[2] = 0;
    imu.gyro_radps[0] = std::numeric_limits<double>::infinity();
    imu.gyro_radps[1] = -std::numeric_limits<double>::infinity();  // their sum is NaN
    CHECK(!record_values_ok(&imu.header));

    auto pos = record<pn_position_t>(PN_REC_POSITION);
    pos.vel_enu_mps[1] = std::numeric_limits<double>::quiet_NaN();  // no velocity flag: not checked
    CHECK(record_values_ok(&pos.header));
    pos.header.flags = PN_POSITION_FLAG_HAS_VELOCITY;
    CHECK(!record_values_ok(&pos.header));
    CHECK(describe(find_value_problem(&pos.header)) == "vel_enu_mps[1] is nan");
    pos.vel_enu_mps[1] = big;
    pos.pos_enu_m[0] = big;
    pos.cov_enu_m2[0] = big;
    CHECK(record_values_ok(&pos.header));

    auto stride = record<pn_stride_t>(PN_REC_STRIDE);
    stride.cov_displacement_m2[8] = std::numeric_limits<double>::quiet_NaN();
    CHECK(!record_values_ok(&stride.header));
    CHECK(describe(find_value_problem(&stride.header)) == "cov_displacement_m2[8] is nan");

    auto att = attitude_of_norm(1.0);
    att.gyro_bias_radps[2] = std::numeric_limits<double>::infinity();
    CHECK(!record_values_ok(&att.header));
    CHECK(describe(find_value_problem(&att.header)) == "gyro_bias_radps[2] is inf");
}
