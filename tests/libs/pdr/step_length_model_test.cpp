// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

#include <pednav_pdr/step_length_model.hpp>

using namespace pednav::pdr;

TEST_CASE("step length: Weinberg's fourth root, an offset, never negative") {
    const StepLengthModel weinberg{0.5, 4.0, 0.0};
    CHECK(step_length_m(weinberg, 16.0) == doctest::Approx(1.0));
    CHECK(step_length_m(weinberg, 0.0) == 0.0);
    CHECK(step_length_m(weinberg, -3.0) == 0.0);
    const StepLengthModel shifted{0.3, 2.0, 0.1};
    CHECK(step_length_m(shifted, 4.0) == doctest::Approx(0.7));
    CHECK(step_length_m(StepLengthModel{0.1, 2.0, -1.0}, 4.0) == 0.0);
}

TEST_CASE("step length: the height default gives the ratio of height at the typical range") {
    const StepLengthModel m = step_length_model_for_height(1.80, 0.415, 5.0, 4.0);
    CHECK(step_length_m(m, 5.0) == doctest::Approx(0.747));
    CHECK(m.beta_m == 0.0);
    CHECK_THROWS_AS(step_length_model_for_height(0.0, 0.415, 5.0, 4.0), std::invalid_argument);
}

namespace {

// A walk of n steps with ranges around `mean_range`, lengths from the model.
CalibrationWalk walk_of(const StepLengthModel& m, int n, double mean_range, double spread) {
    CalibrationWalk w{{}, 0.0};
    for (int i = 0; i < n; ++i) {
        const double r = mean_range + spread * std::sin(0.7 * i);
        w.accel_ranges_mps2.push_back(r);
        w.distance_m += step_length_m(m, r);
    }
    return w;
}

}  // namespace

TEST_CASE("step length fit: recovers k alone, k and beta, and the root") {
    const StepLengthModel truth{0.42, 3.0, 0.12};
    const std::vector<CalibrationWalk> walks = {walk_of(truth, 40, 3.0, 1.0), walk_of(truth, 60, 6.0, 2.0),
                                                walk_of(truth, 30, 9.0, 1.5)};
    const StepLengthFit k_beta = fit_step_length(walks, 3.0, true, 0.0);
    CHECK(k_beta.model.k == doctest::Approx(0.42).epsilon(1e-9));
    CHECK(k_beta.model.beta_m == doctest::Approx(0.12).epsilon(1e-9));
    CHECK(k_beta.rms_relative_error < 1e-9);
    CHECK(k_beta.walks == 3);

    const StepLengthFit k_only = fit_step_length(walks, 3.0, false, 0.12);
    CHECK(k_only.model.k == doctest::Approx(0.42).epsilon(1e-9));

    // Beta left at 0 although it is 0.12: k absorbs part of it, the error shows.
    const StepLengthFit wrong_beta = fit_step_length(walks, 3.0, false, 0.0);
    CHECK(wrong_beta.rms_relative_error > 0.01);

    const StepLengthFit root = fit_step_length_and_root({walk_of({0.5, 2.5, 0.0}, 50, 2.0, 1.5),
                                                         walk_of({0.5, 2.5, 0.0}, 50, 8.0, 3.0)},
                                                        1.5, 6.0, false, 0.0);
    CHECK(root.model.b == doctest::Approx(2.5).epsilon(1e-2));
    CHECK(root.model.k == doctest::Approx(0.5).epsilon(1e-2));
}

TEST_CASE("step length fit: one walk fits k alone even when beta is asked for") {
    const StepLengthModel truth{0.5, 4.0, 0.0};
    const StepLengthFit f = fit_step_length({walk_of(truth, 20, 5.0, 1.0)}, 4.0, true, 0.0);
    CHECK(f.model.beta_m == 0.0);
    CHECK(f.model.k == doctest::Approx(0.5));
}

TEST_CASE("step length fit: refuses walks it cannot use, naming them") {
    CHECK_THROWS_WITH_AS(fit_step_length({}, 4.0, false, 0.0), "step length fit: no walk", std::invalid_argument);
    CHECK_THROWS_WITH_AS(fit_step_length({{{1.0}, 10.0}, {{}, 5.0}}, 4.0, false, 0.0),
                         "step length fit: walk 1 has no step", std::invalid_argument);
    CHECK_THROWS_WITH_AS(fit_step_length({{{1.0}, 0.0}}, 4.0, false, 0.0),
                         "step length fit: walk 0 has no positive distance", std::invalid_argument);
}
