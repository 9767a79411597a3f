// SPDX-License-Identifier: Apache-2.0
// The step/GNSS fusion EKF and the mode choice: the heading convention of
// the model and its Jacobian, the innovation gate, restarting a lost track,
// a step length and a heading offset learnt from GNSS and kept in an outage.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include <pednav/pn_types.h>
#include <pednav_pdr_fusion/gnss_mode.hpp>
#include <pednav_pdr_fusion/step_gnss_ekf.hpp>

#include "../plugin_defaults.hpp"

using namespace pednav::pdr_fusion;

namespace {
const pednav::test::PluginDefaults& defaults() {
    static const pednav::test::PluginDefaults d("libpnp_waist_fusion.so", "org.pednav.waist.fusion");
    return d;
}
StepGnssEkfConfig config() { return step_gnss_ekf_config(defaults()); }
GnssModeConfig mode_config() {
    // gnss_mode_config reads integer() too: PluginDefaults has it.
    return gnss_mode_config(defaults());
}
}  // namespace

TEST_CASE("fusion EKF: azimuth convention, E += L sin psi, N += L cos psi, and its Jacobian") {
    StepGnssEkf ekf(config());
    ekf.start(0, 0, 0, M_PI / 2, 0.7);  // heading east
    ekf.predict_step(0.7, 0.0, 1.8);
    CHECK(ekf.x()(StepGnssEkf::E) == doctest::Approx(0.7));
    CHECK(std::abs(ekf.x()(StepGnssEkf::N)) < 1e-12);
    // A heading change over the step: taken along the mean heading.
    StepGnssEkf turn(config());
    turn.start(0, 0, 0, 0.0, 0.7);
    turn.predict_step(0.7, M_PI / 2, 1.8);
    CHECK(turn.x()(StepGnssEkf::E) == doctest::Approx(0.7 * std::sin(M_PI / 4)));
    CHECK(turn.x()(StepGnssEkf::N) == doctest::Approx(0.7 * std::cos(M_PI / 4)));
    // The covariance grows as the Jacobian of this model says: a heading
    // uncertainty east-bound shows up across track (N), not along it (E).
    StepGnssEkf j(config());
    j.start(0, 0, 0, M_PI / 2, 0.7);
    const double p_ee = j.P()(0, 0), p_nn = j.P()(1, 1);
    j.predict_step(0.7, 0.0, 1.8);
    const double psi_var = j.P()(StepGnssEkf::PSI, StepGnssEkf::PSI);
    CHECK(j.P()(1, 1) - p_nn > 0.49 * (psi_var - 2 * 1e-6) * 0.5);
    CHECK(j.P()(0, 0) - p_ee < j.P()(1, 1) - p_nn);
}

TEST_CASE("fusion EKF: the innovation gate rejects a fix 50 m off and a lost track restarts at consistent fixes") {
    StepGnssEkf ekf(config());
    ekf.start(0, 0, 0, 0.0, 0.7);
    double t = 0;
    for (int k = 0; k < 10; ++k) {
        ekf.predict_step(0.7, 0.0, 1.8);
        CHECK(ekf.gnss_position(0.0, ekf.x()(StepGnssEkf::N) + 0.5, 1.5, 0.0, t += 0.5).accepted);
    }
    const double n_before = ekf.x()(StepGnssEkf::N), e_before = ekf.x()(StepGnssEkf::E);
    const FixResult jump = ekf.gnss_position(50.0, n_before, 1.5, 0.0, t += 1);
    CHECK_FALSE(jump.accepted);
    CHECK(jump.nis > config().gate_chi2);
    CHECK(ekf.x()(StepGnssEkf::E) == e_before);  // the rejected fix changed nothing
    CHECK(ekf.gnss_position(0.0, n_before, 1.5, 0.0, t += 1).accepted);  // back to normal: the count restarts
    // The track was wrong after all: the fixes stay 40 m east, consistently.
    FixResult r;
    for (int k = 0; k < config().gate_max_rejections; ++k) r = ekf.gnss_position(40.0, n_before, 1.5, 0.0, t += 1);
    CHECK(r.recovered);
    CHECK(ekf.x()(StepGnssEkf::E) == doctest::Approx(40.0));
}

TEST_CASE("fusion EKF: a track placed at a fix is as uncertain as the fix, so the next fixes average in") {
    // Fix errors independent from fix to fix (gnss_error_time_s 0).
    StepGnssEkfConfig white = config();
    white.gnss_error_time_s = 0;
    StepGnssEkf ekf(white);
    ekf.start(0, 0, 0, 0.0, 0.7);  // the start point's P0 (init_position_sd_m, 0.1 m)
    ekf.place_at_fix(4.0, 0.0, 3.0, 0.0);  // a first fix 4 m east of the truth at 0, sd 3 m
    CHECK(ekf.x()(StepGnssEkf::E) == doctest::Approx(4.0));
    CHECK(ekf.P()(StepGnssEkf::E, StepGnssEkf::E) == doctest::Approx(9.0));
    CHECK(ekf.P()(StepGnssEkf::E, StepGnssEkf::PSI) == 0.0);
    // Standing, fixes of the same sd alternate about the truth: the track
    // goes to their mean, as an average of all of them (the first included).
    for (int k = 0; k < 9; ++k) CHECK(ekf.gnss_position(k % 2 ? 1.0 : -1.0, 0.0, 3.0, 0.0, k + 1.0).accepted);
    CHECK(ekf.x()(StepGnssEkf::E) == doctest::Approx((4.0 - 1.0) / 10.0).epsilon(1e-6));
    CHECK(ekf.P()(StepGnssEkf::E, StepGnssEkf::E) == doctest::Approx(0.9).epsilon(1e-6));
    // A sd below gnss_min_sd_m is floored there.
    StepGnssEkf tight(config());
    tight.start(0, 0, 0, 0.0, 0.7);
    tight.place_at_fix(1.0, 2.0, 0.0, 0.0);
    CHECK(tight.P()(StepGnssEkf::N, StepGnssEkf::N) == doctest::Approx(config().gnss_min_sd_m * config().gnss_min_sd_m));
    // With correlated fix errors (the default) the track at a fix is as
    // uncertain as the fix, and its error is the fix's correlated part.
    StepGnssEkf gm(config());
    gm.start(0, 0, 0, 0.0, 0.7);
    gm.place_at_fix(4.0, 0.0, 3.0, 0.0);
    const double c2 = 9.0 - config().gnss_white_sd_m * config().gnss_white_sd_m;
    CHECK(gm.P()(StepGnssEkf::E, StepGnssEkf::E) == doctest::Approx(9.0));
    CHECK(gm.P()(StepGnssEkf::BE, StepGnssEkf::BE) == doctest::Approx(c2));
    CHECK(gm.P()(StepGnssEkf::E, StepGnssEkf::BE) == doctest::Approx(-c2));
}

TEST_CASE("fusion EKF: step length and walking direction learnt from GNSS carry through an outage") {
    StepGnssEkf ekf(config());
    const double true_length = 0.8, model_length = 0.7;  // the model is 12.5 % short for this walker
    const double true_psi = 0.5, offset = 0.1;           // the sensor heads 0.1 rad off the walking direction
    ekf.start(0, 0, 0, true_psi - offset, model_length);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, 1.0);
    double e = 0, n = 0;
    for (int k = 0; k < 300; ++k) {  // 240 m with a fix every other step
        ekf.predict_step(model_length, 0.0, 1.8);
        e += true_length * std::sin(true_psi);
        n += true_length * std::cos(true_psi);
        if (k % 2 == 0) {
            ekf.gnss_position(e + 1.0 * noise(rng), n + 1.0 * noise(rng), 1.0, 0.0, k / 1.8);
            const double v = true_length * 1.8;
            ekf.gnss_velocity(v * std::sin(true_psi) + 0.1 * noise(rng), v * std::cos(true_psi) + 0.1 * noise(rng), 0.1);
        }
    }
    CHECK(ekf.x()(StepGnssEkf::L) == doctest::Approx(true_length).epsilon(0.02));
    CHECK(ekf.x()(StepGnssEkf::PSI) == doctest::Approx(true_psi).epsilon(0.04));
    // 100 steps without GNSS: the learnt length and direction stay.
    const double e0 = ekf.x()(StepGnssEkf::E) - e, n0 = ekf.x()(StepGnssEkf::N) - n;
    for (int k = 0; k < 100; ++k) {
        ekf.predict_step(model_length, 0.0, 1.8);
        e += true_length * std::sin(true_psi);
        n += true_length * std::cos(true_psi);
    }
    const double drift = std::hypot(ekf.x()(StepGnssEkf::E) - e - e0, ekf.x()(StepGnssEkf::N) - n - n0);
    CHECK(drift < 0.02 * 100 * true_length);
}

TEST_CASE("fusion EKF: a fix error correlated over a minute is the fixes' (Gauss-Markov states), not the step length's") {
    // 0.8 m steps at 1.8 Hz northwards, the model right; a fix every other
    // step, its error first-order Gauss-Markov (1.5 m per axis, 60 s) plus
    // 0.5 m white, its velocity 0.1 m/s noisy: over a few hundred metres the
    // slowly drifting error looks like a longer or shorter step. Modelled as
    // bE, bN it is not learnt as the step length; taken as white, it is.
    const auto rms_length_error = [](double error_time_s, unsigned seed) {
        StepGnssEkfConfig c = config();
        c.gnss_error_time_s = error_time_s;
        StepGnssEkf ekf(c);
        ekf.start(0, 0, 0, 0.0, 0.8);
        std::mt19937 rng(seed);
        std::normal_distribution<double> noise(0.0, 1.0);
        const double fix_dt_s = 2 / 1.8, phi = std::exp(-fix_dt_s / 60.0);
        double n = 0, sum2 = 0, be = 1.5 * noise(rng), bn = 1.5 * noise(rng);
        int count = 0;
        for (int k = 0; k < 540; ++k) {  // 300 s, 432 m
            ekf.predict_step(0.8, 0.0, 1.8);
            n += 0.8;
            const double t = k / 1.8;
            if (k % 2 == 0) {
                be = phi * be + std::sqrt(1 - phi * phi) * 1.5 * noise(rng);
                bn = phi * bn + std::sqrt(1 - phi * phi) * 1.5 * noise(rng);
                ekf.gnss_position(be + 0.5 * noise(rng), n + bn + 0.5 * noise(rng), std::hypot(1.5, 0.5), 0.0, t);
                ekf.gnss_velocity(0.1 * noise(rng), 1.44 + 0.1 * noise(rng), 0.0);
            }
            if (t > 60) sum2 += std::pow(ekf.x()(StepGnssEkf::L) / 0.8 - 1.0, 2), ++count;
        }
        return std::sqrt(sum2 / count);  // after the first minute
    };
    double gm = 0, white = 0;
    for (unsigned seed = 1; seed <= 8; ++seed)
        gm += rms_length_error(60.0, seed) / 8, white += rms_length_error(0.0, seed) / 8;
    MESSAGE("rms step length error, 8 walks: " << 100 * gm << " % (Gauss-Markov), " << 100 * white << " % (white)");
    CHECK(gm < 0.006);
    CHECK(white > 1.5 * gm);
}

TEST_CASE("GNSS modes: accuracy, satellites and agreement with the steps choose GNSS, fused or steps alone") {
    GnssMode m(mode_config());
    const GnssModeConfig c = mode_config();
    CHECK(m.mode(0) == PositionMode::steps);
    CHECK_FALSE(m.usable(c.max_accuracy_m * 2, 9, PN_GNSS_FIX_AUTONOMOUS));
    CHECK_FALSE(m.usable(3.0, c.min_satellites - 1, PN_GNSS_FIX_AUTONOMOUS));
    CHECK_FALSE(m.usable(3.0, 9, PN_GNSS_FIX_DEAD_RECKONING));
    CHECK(m.usable(3.0, 0, PN_GNSS_FIX_UNKNOWN));  // satellites unknown
    CHECK(m.judge(1000000000, true, 2.0, 9, 1.0) == FixQuality::good);
    CHECK(m.mode(1500000000) == PositionMode::gnss);
    CHECK(m.judge(2000000000, true, c.good_accuracy_m * 1.5, 9, 1.0) == FixQuality::fused);
    CHECK(m.mode(2500000000) == PositionMode::fused);
    CHECK(m.judge(3000000000, true, 2.0, 9, c.consistent_chi2 * 2) == FixQuality::fused);  // disagrees with the steps
    CHECK(m.judge(4000000000, false, 2.0, 9, 100.0) == FixQuality::unusable);  // gated out: the mode stands
    CHECK(m.mode(4000000000) == PositionMode::fused);
    const int64_t after_timeout = 3000000000 + static_cast<int64_t>((c.timeout_s + 0.1) * 1e9);
    CHECK(m.mode(after_timeout) == PositionMode::steps);
}
