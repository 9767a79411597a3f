// SPDX-License-Identifier: Apache-2.0
// The attitude EKF on synthetic sensors: alignment and gyro bias from a
// still period, tilt held by gravity while the sensor rocks, heading from a
// magnetometer the gate accepts, none from one it refuses, the compass
// deviation of a hard-iron field learnt as the sensor turns.
#include <doctest/doctest.h>

#include <cmath>

#include <pednav_attitude_ekf/attitude_ekf.hpp>
#include <pednav_navmath/alignment.hpp>
#include <pednav_navmath/heading.hpp>
#include <pednav_navmath/angles.hpp>

#include "../plugin_defaults.hpp"

using namespace pednav;
using navmath::Quat;
using navmath::Vec3;

namespace {
attitude_ekf::AttitudeEkfConfig defaults() {
    static const test::PluginDefaults d("libpnp_waist_attitude.so", "org.pednav.waist.attitude.ekf9");
    return attitude_ekf::attitude_ekf_config(d);
}
double angle_deg(const Quat& a, const Quat& b) { return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b)))) * 180 / M_PI; }
// The Earth's field in ENU: 48 uT, dip 64 deg, magnetic north = true north.
const Vec3 kField(0.0, 48.0 * std::cos(64 * M_PI / 180), -48.0 * std::sin(64 * M_PI / 180));
}  // namespace

TEST_CASE("attitude EKF: tilt, gyro bias and magnetometer heading of a still, tilted sensor") {
    const Quat truth = navmath::quat_exp(Vec3(0, 0, -50 * M_PI / 180)) * navmath::quat_exp(Vec3(0.5, -0.3, 0.2));
    const Vec3 bias(0.004, -0.003, 0.002);
    attitude_ekf::AttitudeEkf ekf(defaults());
    for (int k = 0; k < 3000; ++k) {  // 30 s at 100 Hz
        const int64_t t = k * 10000000LL;
        if (k % 2 == 0) ekf.on_mag(t, truth.conjugate() * kField);
        ekf.on_imu(t, truth.conjugate() * Vec3(0, 0, 9.81), bias);
    }
    REQUIRE(ekf.aligned());
    CHECK(angle_deg(ekf.q(), truth) < 0.5);
    CHECK(navmath::heading_of(ekf.q()) * 180 / M_PI == doctest::Approx(navmath::heading_of(truth) * 180 / M_PI).epsilon(0.01));
    CHECK((ekf.gyro_bias() - bias).norm() < 2e-4);
    CHECK(ekf.yaw_source() == attitude_ekf::YawSource::magnetometer);
    CHECK(ekf.mag_updates() > 20);
}

TEST_CASE("attitude EKF: a rotating sensor keeps its attitude; a disturbed field is not used") {
    auto config = defaults();
    attitude_ekf::AttitudeEkf ekf(config);
    Quat truth = navmath::quat_exp(Vec3(0.3, 0.2, 0.0));
    const double rate = 100.0;
    int64_t mag_updates_before = 0;
    for (int k = 0; k < 6000; ++k) {
        const int64_t t = static_cast<int64_t>(k * 1e9 / rate);
        const double s = k / rate;
        // Still for 3 s, then turning about the vertical at 0.5 rad/s with a rocking tilt.
        const Vec3 w_enu = s < 3 ? Vec3::Zero() : Vec3(0.2 * std::sin(2 * M_PI * 1.8 * s), 0.0, 0.5);
        const Vec3 w_body = truth.conjugate() * w_enu;
        // 30 to 40 s: steel nearby, the field is 1.5 times as strong.
        const Vec3 field = (s > 30 && s < 40) ? 1.5 * kField : kField;
        if (k % 2 == 0) ekf.on_mag(t, truth.conjugate() * field);
        if (k == 3000) mag_updates_before = ekf.mag_updates();
        if (k == 3950) CHECK(ekf.mag_updates() == mag_updates_before);  // nothing accepted while disturbed
        ekf.on_imu(t, truth.conjugate() * Vec3(0, 0, 9.81), w_body);
        truth = navmath::quat_exp(w_enu / rate) * truth;
    }
    CHECK(angle_deg(ekf.q(), truth) < 1.0);
    CHECK(ekf.mag_updates() > mag_updates_before);
}

TEST_CASE("attitude EKF: without a magnetometer the yaw is the config's, then a GNSS course's, and the app's wins") {
    auto config = defaults();
    config.use_magnetometer = false;
    config.initial_heading_deg = 30;
    attitude_ekf::AttitudeEkf ekf(config);
    for (int k = 0; k < 200; ++k) ekf.on_imu(k * 10000000LL, Vec3(0, 0, 9.81), Vec3::Zero());
    REQUIRE(ekf.aligned());
    CHECK(navmath::heading_of(ekf.q()) * 180 / M_PI == doctest::Approx(30).epsilon(1e-6));
    CHECK(ekf.yaw_source() == attitude_ekf::YawSource::config);
    ekf.on_gnss_course(100 * M_PI / 180, 0.3);  // too slow: no course
    CHECK(ekf.yaw_source() == attitude_ekf::YawSource::config);
    ekf.on_gnss_course(100 * M_PI / 180, 1.4);
    CHECK(navmath::heading_of(ekf.q()) * 180 / M_PI == doctest::Approx(100).epsilon(1e-6));
    CHECK(ekf.yaw_source() == attitude_ekf::YawSource::gnss_course);
    const Quat app = navmath::quat_exp(Vec3(0, 0, M_PI / 4));  // body x from east 45 deg to the left: heading 45 deg
    ekf.set_attitude(app);
    ekf.on_gnss_course(0.0, 1.4);  // ignored from now on
    CHECK(navmath::heading_of(ekf.q()) * 180 / M_PI == doctest::Approx(45).epsilon(1e-6));
}

TEST_CASE("attitude EKF: the compass deviation of a hard-iron field is learnt as the sensor turns") {
    // A tilted sensor with its own field b (body frame, uT) walks a block:
    // 30 s per side, a 90 deg turn at each corner, twice round. The heading
    // the magnetometer gives is off by B sin psi + C cos psi (up to 4 deg
    // here): B = -b.h / B_h, C = b.l / B_h for the level axes h, l.
    const Vec3 hard_iron(1.0, -0.8, 0.5);
    const Quat tilt = navmath::quat_exp(Vec3(0.3, -0.2, 0.0));
    const double b_h = kField.head<2>().norm();
    const auto run = [&](double deviation_sd_rad, Eigen::Vector2d* deviation) {
        auto config = defaults();
        config.mag_deviation_sd_rad = deviation_sd_rad;
        attitude_ekf::AttitudeEkf ekf(config);
        Quat truth = tilt;
        const double rate = 100.0;
        double worst_deg = 0;
        for (int k = 0; k < 26000; ++k) {  // 260 s
            const int64_t t = static_cast<int64_t>(k * 1e9 / rate);
            const double s = k / rate, side = std::fmod(s - 20.0, 30.0);
            // Still 20 s, then 27 s straight and a 3 s turn per side (left, 0.52 rad/s).
            const Vec3 w_enu = s > 20 && side > 27.0 ? Vec3(0, 0, M_PI / 6) : Vec3::Zero();
            if (k % 2 == 0) ekf.on_mag(t, truth.conjugate() * kField + hard_iron);
            ekf.on_imu(t, truth.conjugate() * Vec3(0, 0, 9.81), truth.conjugate() * w_enu);
            truth = navmath::quat_exp(w_enu / rate) * truth;
            if (s > 140 && side < 27.0)  // the second lap, on the straights
                worst_deg = std::max(worst_deg, std::abs(navmath::wrap_pi(navmath::heading_of(ekf.q()) -
                                                                          navmath::heading_of(truth))) * 180 / M_PI);
        }
        if (deviation) *deviation = ekf.mag_deviation_rad();
        return worst_deg;
    };
    const navmath::LevelAxes axes = navmath::level_axes(tilt.conjugate() * Vec3::UnitZ());
    const Eigen::Vector2d expected(-hard_iron.dot(axes.h) / b_h, hard_iron.dot(axes.l) / b_h);
    Eigen::Vector2d learnt;
    const double with = run(defaults().mag_deviation_sd_rad, &learnt), without = run(0.0, nullptr);
    MESSAGE("heading error on the second lap: worst " << with << " deg with the deviation estimated, " << without
                                                      << " deg without; B, C " << learnt.transpose() << " rad (expected "
                                                      << expected.transpose() << ")");
    CHECK((learnt - expected).norm() < 0.15 * expected.norm());
    CHECK(with < 0.5);
    CHECK(without > 4.0 * with);
}
