// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <pednav_navmath/alignment.hpp>
#include <pednav_navmath/heading.hpp>
#include <pednav_navmath/madgwick.hpp>

#include "../plugin_defaults.hpp"

using namespace pednav::navmath;

namespace {

MadgwickConfig defaults() {
    static const pednav::test::PluginDefaults d("libpnp_madgwick.so", "org.pednav.pdr.madgwick");
    return madgwick_config(d);
}

constexpr double kDeg = M_PI / 180.0;

// q_enu_from_body of a sensor at heading h (clockwise from north of its x axis), pitch and roll.
Quat attitude(double heading_deg, double pitch_deg, double roll_deg) {
    const double yaw = (90.0 - heading_deg) * kDeg;  // counter-clockwise from east
    return Quat(Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch_deg * kDeg, Vec3::UnitY()) *
                Eigen::AngleAxisd(roll_deg * kDeg, Vec3::UnitX()));
}

// The Earth field in ENU: 48 uT, dip 64 deg down, magnetic north `decl_deg` east of true north.
Vec3 field_enu(double decl_deg = 0.0) {
    const double h = 48.0 * std::cos(64 * kDeg);
    return {h * std::sin(decl_deg * kDeg), h * std::cos(decl_deg * kDeg), -48.0 * std::sin(64 * kDeg)};
}

// A still sensor at `truth` for `seconds` at 100 Hz: specific force up, the field, zero rate (+ bias).
void still(Madgwick& m, const Quat& truth, double seconds, bool with_mag, const Vec3& gyro_bias = Vec3::Zero(),
           double decl_deg = 0.0, int64_t* t_ns = nullptr) {
    int64_t t = t_ns ? *t_ns : 0;
    const Vec3 f = truth.conjugate() * Vec3(0, 0, 9.81), b = truth.conjugate() * field_enu(decl_deg);
    for (int k = 0; k < static_cast<int>(seconds * 100); ++k) {
        t += 10000000;
        m.update(t, gyro_bias, f, with_mag ? &b : nullptr);
    }
    if (t_ns) *t_ns = t;
}

double angle_between_deg(const Quat& a, const Quat& b) { return a.angularDistance(b) / kDeg; }

}  // namespace

TEST_CASE("madgwick: with zero gain it integrates the gyro exactly (q_dot = 1/2 q (x) omega, ENU)") {
    MadgwickConfig c = defaults();
    c.gain_radps = c.init_gain_radps = 0.0;
    Madgwick m(c);
    m.align(0, Vec3(0, 0, 9.81), 90 * kDeg);  // level, x east
    const Vec3 w(0.0, 0.0, 0.5);              // counter-clockwise about up
    for (int k = 1; k <= 400; ++k) m.update(static_cast<int64_t>(k) * 2500000, w, Vec3(0, 0, 9.81), nullptr);
    // 0.5 rad counter-clockwise: heading 90 deg - 28.65 deg.
    CHECK(heading_of(m.q()) == doctest::Approx((90.0 - 0.5 / kDeg) * kDeg).epsilon(1e-4));
    CHECK(m.up_body().z() == doctest::Approx(1.0));
}

TEST_CASE("madgwick IMU form: the tilt converges to gravity, the heading stays") {
    for (const Quat& truth : {attitude(30, 0, 0), attitude(200, -35, 10), attitude(-75, 50, -40)}) {
        Madgwick m(defaults());
        const Quat start = attitude(heading_of(truth) / kDeg, 0, 0) * Quat(Eigen::AngleAxisd(20 * kDeg, Vec3::UnitX()));
        m.set_attitude(start);
        still(m, truth, 30.0, false);
        const Vec3 up_true = truth.conjugate() * Vec3::UnitZ();
        CHECK((m.up_body() - up_true).norm() < 1e-3);
    }
}

TEST_CASE("madgwick MARG form: the heading converges to the field's, with the declination") {
    for (double decl : {0.0, 12.0})
        for (const Quat& truth : {attitude(0, 0, 0), attitude(120, -30, 20), attitude(-150, 40, -10)}) {
            CAPTURE(decl);
            MadgwickConfig c = defaults();
            c.declination_deg = decl;
            Madgwick m(c);
            // Start 60 deg off in heading, with the right tilt.
            Quat start = truth;
            m.set_attitude(Quat(Eigen::AngleAxisd(60 * kDeg, Vec3::UnitZ())) * start);
            // The field of magnetic north `decl` east of true north; the filter turns it back.
            still(m, truth, 120.0, true, Vec3::Zero(), decl);
            CHECK(angle_between_deg(m.q(), truth) < 0.5);
        }
}

TEST_CASE("madgwick: gyro bias from the gradient (zeta), set_heading keeps the tilt") {
    MadgwickConfig c = defaults();
    c.gyro_bias_gain_radps = 0.02;
    Madgwick m(c);
    const Quat truth = attitude(45, 10, 5);
    m.set_attitude(truth);
    const Vec3 bias(0.01, -0.02, 0.015);
    still(m, truth, 300.0, true, bias);
    CHECK((m.gyro_bias() - bias).norm() < 2e-3);
    CHECK(angle_between_deg(m.q(), truth) < 1.0);

    Madgwick h(defaults());
    h.set_attitude(attitude(10, -30, 15));
    const Vec3 up = h.up_body();
    h.set_heading(-100 * kDeg);
    CHECK(heading_of(h.q()) == doctest::Approx(-100 * kDeg).epsilon(1e-9));
    CHECK((h.up_body() - up).norm() < 1e-12);
    MadgwickConfig bad = defaults();
    bad.max_dt_s = 0;
    CHECK_THROWS_AS(Madgwick{bad}, std::invalid_argument);
}
