// SPDX-License-Identifier: Apache-2.0
// Every metric function on small examples computed by hand.
#include <doctest/doctest.h>

#include <pednav_eval/metrics.hpp>

using namespace pednav::eval;

TEST_CASE("percentile: linear interpolation between order statistics") {
    CHECK(percentile({4, 1, 3, 2}, 75.0) == doctest::Approx(3.25));
    CHECK(percentile({4, 1, 3, 2}, 50.0) == doctest::Approx(2.5));
    CHECK(percentile({5}, 75.0) == 5.0);
    CHECK(percentile({1, 2, 3, 4, 5}, 100.0) == 5.0);
    CHECK(std::isnan(percentile({}, 50.0)));
}

TEST_CASE("standard deviation is the population one; axis and error statistics") {
    CHECK(standard_deviation({2, 4, 4, 4, 5, 5, 7, 9}) == doctest::Approx(2.0));
    const AxisStats a = axis_stats({-1.0, 2.0, 0.5});
    CHECK(a.min == -1.0);
    CHECK(a.max == 2.0);
    CHECK(a.mean == doctest::Approx(0.5));
    CHECK(a.sd == doctest::Approx(std::sqrt((2.25 + 2.25 + 0.0) / 3.0)));
    const ErrorStats e = error_stats({3.0, 1.0, 2.0, 10.0});
    CHECK(e.n == 4);
    CHECK(e.mean == doctest::Approx(4.0));
    CHECK(e.median == doctest::Approx(2.5));
    CHECK(e.p75 == doctest::Approx(4.75));
    CHECK(e.max == 10.0);
    CHECK(e.rms == doctest::Approx(std::sqrt(114.0 / 4.0)));
    CHECK(e.sd == doctest::Approx(std::sqrt((1 + 9 + 4 + 36) / 4.0)));
}

TEST_CASE("angle difference wraps to (-180, 180]") {
    CHECK(angle_diff_deg(10, 350) == doctest::Approx(20));
    CHECK(angle_diff_deg(350, 10) == doctest::Approx(-20));
    CHECK(angle_diff_deg(180, 0) == doctest::Approx(180));
    CHECK(angle_diff_deg(0, 180) == doctest::Approx(180));
    CHECK(angle_diff_deg(725, 0) == doctest::Approx(5));
}

TEST_CASE("IPIN score: 75th percentile of horizontal error plus 15 m per wrong floor") {
    // {1, 2, 3 + 15, 4} sorted {1, 2, 4, 18}: rank 2.25 -> 4 + 0.25 * 14.
    CHECK(ipin_score({1, 2, 3, 4}, {0, 0, 1, 0}) == doctest::Approx(7.5));
    CHECK(ipin_score({1, 2, 3, 4}, {0, 0, -2, 0}) == doctest::Approx(4 + 0.25 * 29));
    CHECK(ipin_score({1, 2, 3, 4}, {0, 0, 0, 0}) == doctest::Approx(3.25));
}

TEST_CASE("loop closure in percent of distance") {
    CHECK(loop_closure_pct(0.36, 120.0) == doctest::Approx(0.3));
    CHECK(std::isnan(loop_closure_pct(1.0, 0.0)));
}

TEST_CASE("Procrustes rotation recovers a known rotation, in least squares") {
    const double th = 30.0 * M_PI / 180.0;
    std::vector<std::array<double, 2>> a{{1, 0}, {2, 1}, {0, 3}}, b;
    for (const auto& p : a)
        b.push_back({std::cos(th) * p[0] - std::sin(th) * p[1], std::sin(th) * p[0] + std::cos(th) * p[1]});
    CHECK(procrustes_rotation_rad(a, b) * 180 / M_PI == doctest::Approx(30.0));
    // Two points at 0 and 90 deg, mapped to 10 and 90 deg: the best rotation splits the difference.
    CHECK(procrustes_rotation_rad({{1, 0}, {0, 1}}, {{std::cos(0.2), std::sin(0.2)}, {0, 1}}) ==
          doctest::Approx(0.1));
}

TEST_CASE("percentile, higher method: the upper order statistic at rank (n - 1) q / 100") {
    CHECK(percentile({4, 1, 3, 2}, 50.0, PercentileMethod::higher) == 3.0);  // rank 1.5 -> the 2nd of 0..3
    CHECK(percentile({4, 1, 3, 2}, 75.0, PercentileMethod::higher) == 4.0);  // rank 2.25
    CHECK(percentile({5, 1, 3}, 50.0, PercentileMethod::higher) == 3.0);     // rank 1: exact
    CHECK(percentile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 90.0, PercentileMethod::higher) == 10.0);  // rank 8.1
    CHECK(percentile({7, 2}, 0.0, PercentileMethod::higher) == 2.0);
    CHECK(percentile({7, 2}, 100.0, PercentileMethod::higher) == 7.0);
    CHECK(std::isnan(percentile({}, 50.0, PercentileMethod::higher)));
}

TEST_CASE("standard deviation with ddof 1 is the sample one") {
    // {2, 4, 4, 4, 5, 5, 7, 9}: squared deviations sum to 32.
    CHECK(standard_deviation({2, 4, 4, 4, 5, 5, 7, 9}, 1) == doctest::Approx(std::sqrt(32.0 / 7.0)));
    CHECK(axis_stats({-1.0, 2.0, 0.5}, 1).sd == doctest::Approx(std::sqrt(4.5 / 2.0)));
    CHECK(std::isnan(standard_deviation({3.0}, 1)));
    CHECK(standard_deviation({3.0}) == 0.0);
}
