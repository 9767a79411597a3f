// SPDX-License-Identifier: Apache-2.0
// The foot INS: the ZUPT of a rolling foot, the accelerometer rescale.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <pednav_zupt_ins/foot_ins.hpp>

#include "../plugin_defaults.hpp"
#include "../test_attitude.hpp"

using namespace pednav::zupt_ins;
using pednav::test::attitude;

namespace {
// The foot EKF plugin's defaults, from its parameter schema.
FootInsConfig foot_ins_defaults() {
    pednav::test::PluginDefaults d("libpnp_foot_ekf.so", "org.pednav.foot.ekf15");
    return foot_ins_config(d);
}
}  // namespace

TEST_CASE("ZUPT on a rolling foot expects the sensor's velocity about the contact point") {
    // The sensor sits tilted and yawed on the foot (R = ENU from body). The
    // foot first moves (velocity about 0.24 m/s east, 0.12 m/s north), then
    // stands on the ground and pitches at 2 rad/s about the ENU north axis
    // through its contact point; the sensor, 0.08 m above the sole, then
    // moves at h (w_n, -w_e, 0) = (0.16, 0, 0) m/s, east. With height 0 (the
    // plain ZUPT) the velocity goes to zero.
    const Mat3 R = attitude(1.1, 0.4, -0.3);
    const Quat q(R);
    const Vec3 w_enu(0.0, 2.0, 0.0), g_enu(0.0, 0.0, 9.80665), push_enu(2.0, 1.0, 0.0);
    const Vec3 w_body = R.transpose() * w_enu;
    for (double height : {0.0, 0.08}) {
        FootInsConfig c = foot_ins_defaults();
        c.sensor_height_m = height;
        c.zupt_lever_m = 0.0;
        c.zaru = false;
        c.hupt = false;
        c.gravity_mps2 = 9.80665;
        FootIns ins(c);
        ins.set_start(Vec3::Zero(), NAN);
        SampleOut out;
        int64_t t = 0;
        for (int k = 0; k < 24; ++k, t += 5'000'000LL)  // 0.12 s of push: v = (0.24, 0.12, 0)
            ins.step(t, R.transpose() * (g_enu + (k > 0 ? push_enu : Vec3::Zero())), Vec3::Zero(), q, Vec3::Zero(),
                     false, out);
        CHECK(out.vel.x() > 0.2);
        for (int k = 0; k < 40; ++k, t += 5'000'000LL)
            ins.step(t, R.transpose() * g_enu, w_body, q, Vec3::Zero(), true, out);
        CAPTURE(height);
        CAPTURE(out.vel.transpose());
        CHECK(std::abs(out.vel.x() - height * w_enu.y()) < 1e-3);
        CHECK(std::abs(out.vel.y() + height * w_enu.x()) < 1e-3);
        CHECK(std::abs(out.vel.z()) < 1e-3);
    }
}

namespace {
// Strides of a foot that stands 1 s, then twice swings 0.7 m east (0.5 s,
// a = A sin(2 pi t / T), back to rest) and stands 0.5 s; the accelerometer
// reads accel_scale times the truth (a level sensor, no rotation).
std::vector<double> stride_lengths_m(const FootInsConfig& c, double accel_scale, bool zero_first_sample = false) {
    const double dt = 0.005, T = 0.5, A = 0.7 * 2.0 * M_PI / (T * T), g = 9.80665;
    FootIns ins(c);
    ins.set_start(Vec3::Zero(), NAN);
    SampleOut out;
    std::vector<double> strides;
    int64_t t_ns = 0;
    bool finite = true;
    const auto sample = [&](double ax, bool stance) {
        const Vec3 a = accel_scale * Vec3(ax, 0.0, g);
        ins.step(t_ns, zero_first_sample && t_ns == 0 ? Vec3::Zero() : a, Vec3::Zero(), Quat::Identity(),
                 Vec3::Zero(), stance, out);
        if (out.stride) strides.push_back(ins.stride_out().displacement.x());
        finite = finite && std::isfinite(out.pos.sum()) && std::isfinite(out.vel.sum());
        t_ns += 5'000'000;
    };
    for (int k = 0; k < 200; ++k) sample(0.0, true);
    for (int step = 0; step < 2; ++step) {
        for (int k = 1; k < 100; ++k) sample(A * std::sin(2.0 * M_PI * k * dt / T), false);
        for (int k = 0; k < 100; ++k) sample(0.0, true);
    }
    StrideOut last;
    if (ins.finish(last)) strides.push_back(last.displacement.x());
    if (!finite) strides.clear();
    return strides;
}
}  // namespace

TEST_CASE("accelerometer rescale: a sensor that reads off gravity at rest gets its strides back when asked") {
    FootInsConfig c = foot_ins_defaults();
    c.hupt = false;
    const auto check_strides = [](const std::vector<double>& s, double expect_m) {
        REQUIRE(s.size() == 2);
        for (double d : s) CHECK(d == doctest::Approx(expect_m).epsilon(0.003));
    };
    // As read (the preset): every stride as long as the scale error makes it.
    check_strides(stride_lengths_m(c, 1.047), 0.7 * 1.047);
    check_strides(stride_lengths_m(c, 0.97), 0.7 * 0.97);
    // Rescaled above 2 %: the 4.7 % and -3 % sensors, not the 1 % one.
    c.accel_rescale_above = 0.02;
    check_strides(stride_lengths_m(c, 1.047), 0.7);
    check_strides(stride_lengths_m(c, 0.97), 0.7);
    check_strides(stride_lengths_m(c, 1.01), 0.7 * 1.01);
    c.accel_rescale_above = 0.0;
    check_strides(stride_lengths_m(c, 1.01), 0.7);
    // Local gravity other than the standard one: a sensor reading 9.80665 at
    // the equator (9.78) reads 0.27 % high.
    c.local_gravity_mps2 = 9.78;
    check_strides(stride_lengths_m(c, 1.0), 0.7 * 9.78 / 9.80665);
    // A first stance that starts with a zero reading (a logger's dropout):
    // no division by it, every output finite.
    c.local_gravity_mps2 = 9.80665;
    c.accel_rescale_above = 0.02;
    CHECK(stride_lengths_m(c, 1.0, true).size() == 2);
}
