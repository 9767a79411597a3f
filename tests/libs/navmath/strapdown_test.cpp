// SPDX-License-Identifier: Apache-2.0
// Strapdown alignment on a still period and attitude integration with coning.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>

#include <pednav_navmath/heading.hpp>
#include <pednav_navmath/strapdown.hpp>

#include "../test_attitude.hpp"
#include "../plugin_defaults.hpp"

using namespace pednav::navmath;
using pednav::test::attitude;
using pednav::test::kDeg;

namespace {
// The strapdown plugin's defaults, from its parameter schema.
StrapdownConfig defaults() {
    pednav::test::PluginDefaults d("libpnp_foot_strapdown.so", "org.pednav.foot.strapdown");
    return strapdown_config(d);
}
}  // namespace

TEST_CASE("strapdown aligns on the still period and takes the heading from a trusted magnetometer") {
    StrapdownConfig c = defaults();
    c.declination_deg = 2.0;
    Strapdown sd(c);
    const Mat3 R = attitude(70 * kDeg, 15 * kDeg, -40 * kDeg);
    const Vec3 f = R.transpose() * Vec3(0, 0, 9.6);  // a sensor reading 0.98 g
    const Vec3 bias(0.01, -0.02, 0.005);
    const Vec3 m = R.transpose() * Vec3(0, 20.0, -40.0);
    bool aligned = false;
    int64_t t = 0;
    for (int k = 0; k < 300 && !aligned; ++k, t += 5000000) {
        sd.on_mag(t, m);
        aligned = sd.on_imu(t, f, bias);
    }
    REQUIRE(aligned);
    CHECK(sd.heading_from_magnetometer());
    CHECK(std::abs(wrap_pi(heading_of(sd.q()) - (70 + 2) * kDeg)) < 1e-6);
    CHECK((sd.gyro_bias() - bias).norm() < 1e-12);
    // Field strength outside the trusted band: heading from the parameter.
    StrapdownConfig c2 = defaults();
    c2.initial_heading_deg = -30.0;
    Strapdown sd2(c2);
    aligned = false;
    t = 0;
    for (int k = 0; k < 300 && !aligned; ++k, t += 5000000) {
        sd2.on_mag(t, m * 0.01);
        aligned = sd2.on_imu(t, f, bias);
    }
    REQUIRE(aligned);
    CHECK_FALSE(sd2.heading_from_magnetometer());
    CHECK(std::abs(wrap_pi(heading_of(sd2.q()) + 30 * kDeg)) < 1e-6);
}

TEST_CASE("attitude integration with mid-interval rates and coning is exact for a coning motion") {
    // Classic coning: the body rotates about a cone; the exact attitude is known.
    const double rate = 400.0, dt = 1.0 / rate;
    const double cone = 0.3, spin = 2 * M_PI * 2.0;  // half-angle (rad), cone frequency (rad/s)
    auto q_true = [&](double t) {
        // q(t) = exp(cone * [cos(spin t), sin(spin t), 0]) about a rotating axis, relative to the start.
        return quat_exp(cone * Vec3(std::cos(spin * t), std::sin(spin * t), 0.0));
    };
    auto body_rate = [&](double t) {
        // Numerical body rate from the exact attitude: w = 2 Im(q^-1 dq/dt).
        const double h = 1e-6;
        const Quat d = q_true(t).conjugate() * q_true(t + h);
        const Quat d0 = q_true(t - h).conjugate() * q_true(t);
        return Vec3((quat_log(d) + quat_log(d0)) / (2 * h));
    };
    const StrapdownConfig c = defaults();
    Strapdown sd(c);
    sd.set_attitude(q_true(0.0));
    const Vec3 f(0, 0, 9.81);
    int64_t t_ns = 0;
    sd.on_imu(t_ns, f, body_rate(0.0));
    for (int k = 1; k <= static_cast<int>(2.0 * rate); ++k) {
        t_ns = static_cast<int64_t>(std::llround(k * dt * 1e9));
        sd.on_imu(t_ns, f, body_rate(k * dt));
    }
    const double err = quat_log(sd.q().conjugate() * q_true(2.0)).norm();
    // Two seconds of 0.3 rad coning at 2 Hz (peak rate 3.8 rad/s): drift below 0.05 deg.
    CHECK(err < 0.05 * kDeg);
}
