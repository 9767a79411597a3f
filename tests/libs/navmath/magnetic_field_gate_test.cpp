// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include <pednav_navmath/magnetic_field_gate.hpp>

using namespace pednav::navmath;

namespace {

MagneticFieldGateConfig learning_config() {
    MagneticFieldGateConfig c;
    c.field_ut = 0;
    c.dip_deg = std::nan("");
    c.field_tolerance_ut = 6.0;
    c.dip_tolerance_deg = 5.0;
    c.learn_s = 2.0;
    return c;
}

// The Earth's field of strength f and dip d (deg) seen by a body rotated by q.
Vec3 field_in_body(double f, double d, const Quat& q_enu_from_body) {
    const double dr = d * M_PI / 180.0;
    const Vec3 enu(0.0, f * std::cos(dr), -f * std::sin(dr));
    return q_enu_from_body.conjugate() * enu;
}

}  // namespace

TEST_CASE("magnetic gate: dip from the up direction in any attitude") {
    for (double roll : {0.0, 0.4, -1.2})
        for (double yaw : {0.0, 2.0}) {
            const Quat q = Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(roll, Vec3::UnitX()));
            const Vec3 up_body = q.conjugate() * Vec3::UnitZ();
            CHECK(MagneticFieldGate::dip_of_deg(field_in_body(48.0, 64.0, q), up_body) == doctest::Approx(64.0));
            CHECK(MagneticFieldGate::dip_of_deg(field_in_body(30.0, -20.0, q), up_body) == doctest::Approx(-20.0));
        }
}

TEST_CASE("magnetic gate: learns the local field by medians, then refuses disturbed readings") {
    MagneticFieldGate gate(learning_config());
    const Quat q = Quat::Identity();
    const Vec3 up = Vec3::UnitZ();
    int64_t t = 0;
    // 2 s at 100 Hz; a steel door disturbs a fifth of it.
    for (int i = 0; i <= 200; ++i, t += 10'000'000) {
        const bool door = i > 40 && i < 80;
        CHECK(gate.accept(t, field_in_body(door ? 60.0 : 48.0, door ? 40.0 : 64.0, q), up));
    }
    REQUIRE(gate.learnt());
    CHECK(gate.field_ut() == doctest::Approx(48.0));
    CHECK(gate.dip_deg() == doctest::Approx(64.0));
    CHECK(gate.accept(t, field_in_body(52.0, 61.0, q), up));
    CHECK(!gate.accept(t, field_in_body(58.0, 64.0, q), up));   // strength off by 10 uT
    CHECK(!gate.accept(t, field_in_body(48.0, 55.0, q), up));   // dip off by 9 deg
    CHECK(gate.last_dip_deg() == doctest::Approx(55.0));
    // A field outside the Earth's range is not accepted while learning.
    gate.reset();
    CHECK(!gate.learnt());
    CHECK(!gate.accept(0, field_in_body(150.0, 64.0, q), up));
}

TEST_CASE("magnetic gate: a configured field is used from the first reading") {
    MagneticFieldGateConfig c = learning_config();
    c.field_ut = 48.0;
    c.dip_deg = 64.0;
    MagneticFieldGate gate(c);
    CHECK(gate.learnt());
    CHECK(!gate.accept(0, field_in_body(30.0, 64.0, Quat::Identity()), Vec3::UnitZ()));
    CHECK(gate.accept(0, field_in_body(47.0, 66.0, Quat::Identity()), Vec3::UnitZ()));
    c.dip_tolerance_deg = 0;
    CHECK_THROWS_AS(MagneticFieldGate{c}, std::invalid_argument);
}
