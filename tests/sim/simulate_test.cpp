// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include <Eigen/Dense>

#include <pednav_sim/simulate.hpp>

using namespace pednav::sim;

namespace {

SimOutput run(const std::string& route, const std::string& mount, bool errors, uint64_t seed = 1,
              double rate = 200.0) {
    SimOptions o;
    o.mount = mount;
    o.sensor_errors = errors;
    o.seed = seed;
    o.rate_hz = rate;
    return simulate(builtin_route(route), o);
}

}  // namespace

TEST_CASE("truth: velocity is the derivative of position, and the trajectory is continuous") {
    for (const char* mount : {"foot", "chest", "waist"}) {
        for (const std::string& route : builtin_route_names()) {
            CAPTURE(mount);
            CAPTURE(route);
            const SimOutput o = run(route, mount, false, 1, 400.0);
            double worst = 0.0, worst_t = 0.0, worst_jump = 0.0;
            for (size_t k = 1; k + 1 < o.truth.size(); ++k) {
                const double dt = o.truth[k + 1].t_s - o.truth[k - 1].t_s;
                for (int i = 0; i < 3; ++i) {
                    const double fd = (o.truth[k + 1].pos_enu_m[i] - o.truth[k - 1].pos_enu_m[i]) / dt;
                    const double e = std::fabs(fd - o.truth[k].vel_enu_mps[i]);
                    if (e > worst) worst = e, worst_t = o.truth[k].t_s;
                    worst_jump = std::max(worst_jump,
                                          std::fabs(o.truth[k].pos_enu_m[i] - o.truth[k - 1].pos_enu_m[i]));
                }
            }
            CAPTURE(worst_t);
            CHECK(worst < 2e-3);       // central difference error at 400 Hz, m/s
            CHECK(worst_jump < 0.03);  // at most 12 m/s for one sample
        }
    }
}

TEST_CASE("determinism: the same seed gives bit-identical records, another seed different ones") {
    const SimOutput a = run("stairs", "foot", true, 7), b = run("stairs", "foot", true, 7),
                    c = run("stairs", "foot", true, 8);
    REQUIRE(a.imu.size() == b.imu.size());
    CHECK(std::memcmp(a.imu.data(), b.imu.data(), a.imu.size() * sizeof(pn_imu_t)) == 0);
    CHECK(std::memcmp(a.mag.data(), b.mag.data(), a.mag.size() * sizeof(pn_mag_t)) == 0);
    CHECK(std::memcmp(a.baro.data(), b.baro.data(), a.baro.size() * sizeof(pn_baro_t)) == 0);
    CHECK(std::memcmp(a.imu.data(), c.imu.data(), a.imu.size() * sizeof(pn_imu_t)) != 0);
    // Timing is exact: sample k at k / rate.
    CHECK(a.imu[1000].header.t_ns == 5000000000LL);
    CHECK(a.truth[1000].t_s == 5.0);
}

TEST_CASE("corridor_loop, foot: 120 m, 86 strides, closes exactly, realistic stances and pitch") {
    const SimOutput o = run("corridor_loop", "foot", false);
    CHECK(o.distance_m == doctest::Approx(120.0).epsilon(1e-12));
    // 40 m sides in 29 strides, 20 m sides in 14 (nominal stride 1.4 m).
    CHECK(o.step_times_s.size() == 86);
    const TruthSample& first = o.truth.front();
    const TruthSample& last = o.truth.back();
    for (int i = 0; i < 3; ++i) CHECK(last.pos_enu_m[i] == doctest::Approx(first.pos_enu_m[i]).scale(1e-9));
    // Stances: the first lasts the opening still period; regular ones 0.25-0.35 s.
    std::vector<double> stances;
    double start = 0.0;
    for (size_t k = 1; k < o.truth.size(); ++k) {
        if (o.truth[k].stance && !o.truth[k - 1].stance) start = o.truth[k].t_s;
        if (!o.truth[k].stance && o.truth[k - 1].stance) stances.push_back(o.truth[k].t_s - start);
    }
    REQUIRE(stances.size() == 86);  // the opening stance and 85 regular ones before the last stride
    for (size_t i = 1; i < stances.size(); ++i) {
        CHECK(stances[i] > 0.25);
        CHECK(stances[i] < 0.35);
    }
    CHECK(stances[0] == doctest::Approx(10.0).epsilon(0.001));
    // Pitch of the foot (rotation about its left axis, positive toes down): toe-off and heel strike.
    double max_pitch = -1.0, min_pitch = 1.0, max_speed = 0.0;
    for (const TruthSample& t : o.truth) {
        const Eigen::Quaterniond q(t.q_enu_from_body[0], t.q_enu_from_body[1], t.q_enu_from_body[2],
                                   t.q_enu_from_body[3]);
        const Eigen::Vector3d x = q * Eigen::Vector3d::UnitX();
        const double pitch = std::asin(-x.z());
        max_pitch = std::max(max_pitch, pitch);
        min_pitch = std::min(min_pitch, pitch);
        max_speed = std::max(max_speed, Eigen::Vector3d(t.vel_enu_mps).norm());
    }
    CHECK(max_pitch * 180 / M_PI == doctest::Approx(55.0).epsilon(0.05));
    CHECK(min_pitch * 180 / M_PI == doctest::Approx(-25.0).epsilon(0.1));
    CHECK(max_speed > 3.0);
    CHECK(max_speed < 6.0);
}

TEST_CASE("stairs, foot: up two flights to floor 1 and back, no heel strike on the stairs") {
    const SimOutput o = run("stairs", "foot", false);
    double max_z = 0.0;
    int max_floor = 0;
    for (const TruthSample& t : o.truth)
        max_z = std::max(max_z, t.pos_enu_m[2]), max_floor = std::max(max_floor, t.floor);
    CHECK(max_z ==
          doctest::Approx(3.4 + 0.08).epsilon(0.02));  // floor 1 plus the swing's clearance... at most
    CHECK(max_floor == 1);
    CHECK(o.truth.back().pos_enu_m[2] == doctest::Approx(0.0).scale(1e-9));
    CHECK(o.truth.back().floor == 0);
    // While the foot is between floors (on a flight) it never pitches toes-up.
    double min_pitch_on_stairs = 0.0;
    for (const TruthSample& t : o.truth) {
        if (t.pos_enu_m[0] < 10.05 || t.pos_enu_m[0] > 12.75) continue;  // the flights span x in [10, 12.8]
        const Eigen::Quaterniond q(t.q_enu_from_body[0], t.q_enu_from_body[1], t.q_enu_from_body[2],
                                   t.q_enu_from_body[3]);
        min_pitch_on_stairs = std::min(min_pitch_on_stairs, std::asin(-(q * Eigen::Vector3d::UnitX()).z()));
    }
    CHECK(min_pitch_on_stairs > -1e-9);
}

TEST_CASE(
    "stairs, chest: the truth's floor changes on arrival, the half-way landing belongs to the floor left") {
    const SimOutput o = run("stairs", "chest", false);
    int changes = 0;
    for (size_t k = 1; k < o.truth.size(); ++k) {
        const TruthSample &a = o.truth[k - 1], &b = o.truth[k];
        const double walked_m = b.pos_enu_m[2] - 1.35;  // the chest is 1.35 m above the floor walked on
        if (b.floor != a.floor) {
            ++changes;
            // Within a stair's rise of the floor arrived at, never on the landing (1.7 m).
            CHECK(std::fabs(walked_m - 3.4 * b.floor) < 0.1);
        }
        if (std::fabs(walked_m - 1.7) < 0.05) CHECK(b.floor == (b.t_s < 40.0 ? 0 : 1));  // up, then down
    }
    CHECK(changes == 2);  // the bounce on the landing flips nothing
}

TEST_CASE("chest and waist: every step counted, bounce of a few cm, standing still at both ends") {
    for (const char* mount : {"chest", "waist"}) {
        CAPTURE(mount);
        const SimOutput o = run("corridor_loop", mount, false);
        CHECK(o.step_times_s.size() == 2 * 86);
        CHECK(o.distance_m == doctest::Approx(120.0));
        double zmin = 1e9, zmax = -1e9;
        for (const TruthSample& t : o.truth)
            if (t.t_s > 30.0 && t.t_s < 40.0)
                zmin = std::min(zmin, t.pos_enu_m[2]), zmax = std::max(zmax, t.pos_enu_m[2]);
        CHECK(zmax - zmin > 0.03);
        CHECK(zmax - zmin < 0.08);
        CHECK(o.truth.front().stance == 1);
        CHECK(o.truth.back().stance == 1);
        const TruthSample& last = o.truth.back();
        CHECK(std::hypot(last.pos_enu_m[0], last.pos_enu_m[1]) < 1e-9);
    }
}

TEST_CASE("sensor model: exact readings at rest when errors are off, realistic noise and bias when on") {
    const SimOutput exact = run("corridor_loop", "foot", false);
    const pn_imu_t& r = exact.imu[100];
    CHECK(r.accel_mps2[0] == doctest::Approx(0.0).scale(1e-12));
    CHECK(r.accel_mps2[2] == doctest::Approx(9.80665));
    CHECK(r.gyro_radps[1] == 0.0);
    const double bnorm = Eigen::Vector3d(exact.mag[100].mag_ut).norm();
    CHECK(bnorm == doctest::Approx(48.0));
    // The foot faces east at the start: the field's horizontal part points north-ish, to the left (+y).
    CHECK(exact.mag[100].mag_ut[1] > 20.0);

    const SimOutput noisy = run("corridor_loop", "foot", true);
    // Over the 10 s still period: mean = bias (drawn, nonzero), spread = white noise.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero(), sq = Eigen::Vector3d::Zero();
    const int n = 1800;
    for (int k = 0; k < n; ++k) mean += Eigen::Vector3d(noisy.imu[k].gyro_radps) / n;
    for (int k = 0; k < n; ++k) sq += (Eigen::Vector3d(noisy.imu[k].gyro_radps) - mean).cwiseAbs2() / n;
    const double sigma = 1.2e-4 * std::sqrt(200.0);
    for (int i = 0; i < 3; ++i) CHECK(std::sqrt(sq[i]) == doctest::Approx(sigma).epsilon(0.1));
    CHECK(mean.norm() > 3 * sigma / std::sqrt(double(n)));
    CHECK(mean.norm() < 0.03);
}

TEST_CASE("barometer and GNSS: floors in pascals, fixes only outdoors") {
    const SimOutput o = run("stairs", "chest", false);
    double pmin = 1e9, pmax = 0;
    for (const pn_baro_t& b : o.baro)
        pmin = std::min(pmin, b.pressure_pa), pmax = std::max(pmax, b.pressure_pa);
    CHECK(pmax - pmin == doctest::Approx(3.4 * 1.18 * 9.80665).epsilon(0.08));  // rho g dh, plus the bounce
    CHECK(o.gnss.empty());                                                      // all indoors

    const SimOutput w = run("outdoor_indoor", "waist", true);
    REQUIRE(!w.gnss.empty());
    const Route route = builtin_route("outdoor_indoor");
    for (const pn_gnss_t& g : w.gnss) {
        const size_t k = static_cast<size_t>(g.header.t_ns / 5000000);
        const double x = w.truth[k].pos_enu_m[0], y = w.truth[k].pos_enu_m[1];
        CHECK_FALSE((x > 50.5 && y > -1.0 && y < 21.0));  // never inside the building
        CHECK(g.h_accuracy_m > 1.0);
    }
    // Outside for 20 s + ~50 m + ~70 m at 1.3 m/s: about 110 fixes.
    CHECK(w.gnss.size() > 90);
    CHECK(w.gnss.size() < 130);
    const auto recs = w.records();
    CHECK(recs.size() == w.imu.size() + w.mag.size() + w.baro.size() + w.gnss.size());
    for (size_t i = 1; i < recs.size(); ++i) CHECK(recs[i]->t_ns >= recs[i - 1]->t_ns);
}

TEST_CASE("heel strike transient: the requested peak on level floors, still exact truth") {
    SimOptions o;
    o.sensor_errors = false;
    o.heel_strike_g = 5.0;
    o.rate_hz = 1000.0;
    const SimOutput hit = simulate(builtin_route("corridor_loop"), o);
    o.heel_strike_g = 0.0;
    const SimOutput soft = simulate(builtin_route("corridor_loop"), o);
    double peak_hit = 0.0, peak_soft = 0.0, worst = 0.0;
    for (size_t k = 0; k < hit.imu.size(); ++k) {
        peak_hit = std::max(peak_hit, Eigen::Vector3d(hit.imu[k].accel_mps2).norm());
        peak_soft = std::max(peak_soft, Eigen::Vector3d(soft.imu[k].accel_mps2).norm());
    }
    for (size_t k = 1; k + 1 < hit.truth.size(); ++k) {
        const double dt = hit.truth[k + 1].t_s - hit.truth[k - 1].t_s;
        const double fd = (hit.truth[k + 1].pos_enu_m[2] - hit.truth[k - 1].pos_enu_m[2]) / dt;
        worst = std::max(worst, std::fabs(fd - hit.truth[k].vel_enu_mps[2]));
    }
    MESSAGE("peak specific force: " << peak_soft / 9.80665 << " g without, " << peak_hit / 9.80665
                                    << " g with a 5 g transient");
    CHECK(peak_hit > peak_soft + 3.0 * 9.80665);
    CHECK(worst < 5e-3);  // central-difference error at 1 kHz; a wrong derivative would be ~0.3 m/s off
    // Stances and step events do not move.
    CHECK(hit.step_times_s == soft.step_times_s);
}
