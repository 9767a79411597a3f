// SPDX-License-Identifier: Apache-2.0
// The simulator's self-test: with every sensor error off, integrating the
// simulated IMU from the true initial state reproduces the truth.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "strapdown_reference.hpp"

namespace {

using namespace pednav::sim;

struct Drift {
    double max_pos_m = 0.0, final_pos_m = 0.0, max_att_rad = 0.0, seconds = 0.0;
};

Drift drift_over(const SimOutput& out, double seconds, double gravity) {
    const size_t first = 0;
    const size_t last =
        std::min(out.imu.size() - 1, static_cast<size_t>(std::llround(seconds * out.rate_hz)));
    const auto nav =
        test::integrate_rk4(out.imu, first, last, test::state_from_truth(out.truth[first]), gravity);
    Drift d;
    d.seconds = out.truth[last].t_s - out.truth[first].t_s;
    for (size_t k = 0; k < nav.size(); ++k) {
        const TruthSample& t = out.truth[first + k];
        const double e = (nav[k].p_enu_m - Eigen::Vector3d(t.pos_enu_m)).norm();
        d.max_pos_m = std::max(d.max_pos_m, e);
        const Eigen::Quaterniond qt(t.q_enu_from_body[0], t.q_enu_from_body[1], t.q_enu_from_body[2],
                                    t.q_enu_from_body[3]);
        d.max_att_rad = std::max(d.max_att_rad, qt.angularDistance(nav[k].q_enu_from_body));
        if (k + 1 == nav.size()) d.final_pos_m = e;
    }
    return d;
}

SimOutput exact(const std::string& route, const std::string& mount, double rate_hz,
                const double rpy_deg[3] = nullptr) {
    SimOptions o;
    o.mount = mount;
    o.rate_hz = rate_hz;
    o.sensor_errors = false;
    o.with_mag = o.with_baro = o.with_gnss = false;
    if (rpy_deg)
        for (int i = 0; i < 3; ++i) o.mounting_rpy_deg[i] = rpy_deg[i];
    return simulate(builtin_route(route), o);
}

}  // namespace

TEST_CASE("self-test: exact foot IMU integrates back to the truth over a minute of walking") {
    struct Case {
        const char* route;
        double rate_hz;
        double rpy[3];
    } cases[] = {{"corridor_loop", 200.0, {0, 0, 0}},
                 {"corridor_loop", 250.0, {0, 0, 0}},
                 {"corridor_loop", 400.0, {10, -35, 170}},
                 {"stairs", 200.0, {0, 0, 0}},
                 {"figure_eight", 200.0, {0, 0, 0}}};
    for (const Case& c : cases) {
        CAPTURE(c.route);
        CAPTURE(c.rate_hz);
        const SimOutput out = exact(c.route, "foot", c.rate_hz, c.rpy);
        const Drift d = drift_over(out, 70.0, 9.80665);  // 10 s standing + 60 s walking
        std::printf(
            "self-test foot %-14s %5.0f Hz rpy(%g,%g,%g): over %.0f s max position error %.4f m, final %.4f "
            "m, "
            "max attitude error %.2e rad\n",
            c.route, c.rate_hz, c.rpy[0], c.rpy[1], c.rpy[2], d.seconds, d.max_pos_m, d.final_pos_m,
            d.max_att_rad);
        CHECK(d.seconds >= 69.9);
        CHECK(d.max_pos_m < 0.03);
        CHECK(d.max_att_rad < 1e-4);
    }
}

TEST_CASE(
    "self-test: the error shrinks with the sample rate at the integrator's order (chest, waist, foot)") {
    // A consistent simulator: a 4th-order integration error falls ~16x when the rate doubles,
    // a 2nd-order one ~4x. An inconsistency (a wrong angular-rate formula) would not shrink at all.
    for (const char* mount : {"foot", "chest", "waist"}) {
        CAPTURE(mount);
        const SimOutput lo = exact("corridor_loop", mount, 100.0), hi = exact("corridor_loop", mount, 200.0);
        const auto run = [](const SimOutput& o, bool rk4) {
            const size_t last = static_cast<size_t>(std::llround(40.0 * o.rate_hz));
            const auto nav =
                rk4 ? test::integrate_rk4(o.imu, 0, last, test::state_from_truth(o.truth[0]), 9.80665)
                    : test::integrate(o.imu, 0, last, test::state_from_truth(o.truth[0]), 9.80665);
            return (nav.back().p_enu_m - Eigen::Vector3d(o.truth[last].pos_enu_m)).norm();
        };
        const double e2_lo = run(lo, false), e2_hi = run(hi, false), e4_lo = run(lo, true),
                     e4_hi = run(hi, true);
        std::printf(
            "self-test %-5s over 40 s: 2nd-order integrator %.4f m (100 Hz) %.4f m (200 Hz); "
            "4th-order %.5f m (100 Hz) %.5f m (200 Hz)\n",
            mount, e2_lo, e2_hi, e4_lo, e4_hi);
        if (std::string(mount) == "foot") {
            CHECK(e2_hi < e2_lo / 3.0);
            CHECK(e4_hi < e4_lo / 10.0);
        }
        CHECK(e4_hi < 0.01);
    }
}
