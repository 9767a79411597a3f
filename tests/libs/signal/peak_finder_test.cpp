// SPDX-License-Identifier: Apache-2.0
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <pednav_signal/peak_finder.hpp>

using namespace pednav::signal;

namespace {

struct Found {
    std::vector<Peak> peaks;
    std::vector<int64_t> reported_at_ns;
};

template <class F>
Found run(const PeakFinderConfig& c, double rate_hz, double seconds, F signal) {
    PeakFinder f(c);
    Found out;
    Peak p;
    for (int k = 0; k < static_cast<int>(seconds * rate_hz); ++k) {
        const int64_t t = static_cast<int64_t>(std::llround(k * 1e9 / rate_hz));
        if (f.push(t, signal(k / rate_hz), p)) {
            out.peaks.push_back(p);
            out.reported_at_ns.push_back(t);
        }
    }
    return out;
}

}  // namespace

TEST_CASE("peaks: one per period, at the maximum, with the valley before it, within confirm_s") {
    const PeakFinderConfig c{0.3, 0.5, 0.4, 0.25};
    const Found f = run(c, 200.0, 10.0, [](double t) { return 2.0 * std::sin(2 * M_PI * 1.8 * t); });
    REQUIRE(f.peaks.size() == 18);
    for (size_t i = 0; i < f.peaks.size(); ++i) {
        const double t = f.peaks[i].t_ns * 1e-9;
        // Maxima at (0.25 + k) / 1.8 s.
        CHECK(std::fabs(t * 1.8 - 0.25 - static_cast<double>(i)) < 0.01);
        CHECK(f.peaks[i].value == doctest::Approx(2.0).epsilon(0.001));
        if (i > 0) CHECK(f.peaks[i].valley == doctest::Approx(-2.0).epsilon(0.001));
        CHECK(f.reported_at_ns[i] - f.peaks[i].t_ns <= 250000000);
    }
}

TEST_CASE("peaks: the double bump of one step is one peak, low bumps are none") {
    const PeakFinderConfig c{0.3, 0.5, 0.3, 0.25};
    // Every 0.6 s a main bump and a smaller one 0.12 s later (a heel strike's double peak), and a 0.3 bump between.
    auto signal = [](double t) {
        const double u = std::fmod(t, 0.6);
        return 1.5 * std::exp(-std::pow((u - 0.1) / 0.03, 2)) + 1.2 * std::exp(-std::pow((u - 0.22) / 0.03, 2)) +
               0.3 * std::exp(-std::pow((u - 0.45) / 0.03, 2));
    };
    const Found f = run(c, 400.0, 6.0, signal);
    REQUIRE(f.peaks.size() == 10);
    for (const Peak& p : f.peaks) CHECK(std::fabs(std::fmod(p.t_ns * 1e-9, 0.6) - 0.1) < 0.005);
}
