// SPDX-License-Identifier: Apache-2.0
// The stance detectors on synthetic walks and runs at several rates.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <pednav_navmath/so3.hpp>
#include <pednav_zupt_ins/stance_detector.hpp>

#include "../plugin_defaults.hpp"

using namespace pednav::zupt_ins;
using pednav::navmath::Vec3;

namespace {
// The stance plugins' defaults, from their parameter schemas.
MultiConditionConfig multicondition_defaults() {
    pednav::test::PluginDefaults d("libpnp_foot_stance.so", "org.pednav.foot.stance.multicondition");
    return multicondition_config(d);
}
ShoeConfig shoe_defaults() {
    pednav::test::PluginDefaults d("libpnp_foot_stance.so", "org.pednav.foot.stance.shoe");
    return shoe_config(d);
}
struct Synthetic {
    std::vector<int64_t> t_ns;
    std::vector<Vec3> a, w;
    std::vector<int> stance;
};

// Walking or running: stance (foot flat, gravity at `g_read` along a tilted
// axis, plus the small roll of a real foot) then swing (large rotation and
// acceleration), with white noise.
Synthetic gait(double rate_hz, double stance_s, double swing_s, double g_read, int cycles, double roll_rate,
               double swing_scale, uint32_t seed) {
    Synthetic s;
    std::mt19937 rng(seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    const Vec3 up = Vec3(0.5, 0.2, -0.84).normalized();  // tilted, z down
    const double period = stance_s + swing_s;
    const int n = static_cast<int>((0.8 + cycles * period + 0.5 * stance_s) * rate_hz);  // ends mid-stance
    for (int k = 0; k < n; ++k) {
        const double t = k / rate_hz;
        const double tc = t < 0.8 ? -1.0 : std::fmod(t - 0.8, period);
        const bool st = tc < 0 || tc < stance_s;
        Vec3 a = g_read * up, w = Vec3::Zero();
        if (!st) {
            const double ph = (tc - stance_s) / swing_s;  // 0..1
            const double env = std::sin(M_PI * ph);
            w = swing_scale * env * Vec3(1.0, 5.0 * std::sin(2 * M_PI * ph), 0.8);
            a += swing_scale * env * Vec3(12.0 * std::sin(2 * M_PI * ph), 3.0, 8.0 * std::cos(2 * M_PI * ph));
        } else if (tc >= 0) {
            w = roll_rate * std::sin(M_PI * tc / stance_s) * Vec3(0.0, 1.0, 0.2);  // heel-to-toe roll
        }
        a += 0.05 * Vec3(n01(rng), n01(rng), n01(rng));
        w += 0.01 * Vec3(n01(rng), n01(rng), n01(rng));
        s.t_ns.push_back(static_cast<int64_t>(std::llround(t * 1e9)));
        s.a.push_back(a);
        s.w.push_back(w);
        s.stance.push_back(st ? 1 : 0);
    }
    return s;
}

int segments_of(const std::vector<int>& stance) {
    int n = 0, prev = 0;
    for (int s : stance) {
        n += s && !prev;
        prev = s;
    }
    return n;
}

struct DetectionScore {
    int segments = 0;
    double agreement = 0;  // share of samples whose decision equals the truth
    bool latency_kept = true;
    size_t outputs = 0;
};

DetectionScore detect(StanceDetector& d, const Synthetic& s) {
    std::vector<StanceDecision> out;
    DetectionScore sc;
    for (size_t k = 0; k < s.t_ns.size(); ++k) {
        const size_t before = out.size();
        d.push(s.t_ns[k], s.a[k].data(), s.w[k].data(), [&](const StanceDecision& x) { out.push_back(x); });
        // Every decision about t is out once input t + latency is in, not later.
        for (size_t j = before; j < out.size(); ++j)
            if (k > 0 && s.t_ns[k - 1] >= out[j].t_ns + d.latency_ns()) sc.latency_kept = false;
        const size_t due = static_cast<size_t>(
            std::upper_bound(s.t_ns.begin(), s.t_ns.end(), s.t_ns[k] - d.latency_ns()) - s.t_ns.begin());
        if (out.size() < due) sc.latency_kept = false;
    }
    d.flush([&](const StanceDecision& x) { out.push_back(x); });
    sc.outputs = out.size();
    int agree = 0, prev = 0;
    for (size_t k = 0; k < out.size() && k < s.t_ns.size(); ++k) {
        REQUIRE(out[k].t_ns == s.t_ns[k]);
        agree += (out[k].stance ? 1 : 0) == s.stance[k];
        if (out[k].stance && !prev) ++sc.segments;
        prev = out[k].stance;
    }
    sc.agreement = static_cast<double>(agree) / s.t_ns.size();
    return sc;
}
}  // namespace

TEST_CASE("stance detectors give the same decisions at 100, 200, 250 and 400 Hz on a 0.97 g sensor") {
    for (double rate : {100.0, 200.0, 250.0, 400.0}) {
        CAPTURE(rate);
        const Synthetic walk = gait(rate, 0.35, 0.65, 0.97 * 9.80665, 12, 0.3, 1.0, 7);
        MultiConditionConfig mc = multicondition_defaults();
        StanceDetector multi(mc, 1000.0);
        const DetectionScore a = detect(multi, walk);
        CHECK(a.outputs == walk.t_ns.size());
        CHECK(a.latency_kept);
        const int truth = segments_of(walk.stance);
        CHECK(truth == 13);  // the opening still period runs into the first stance
        CHECK(a.segments == truth);
        CHECK(a.agreement > 0.9);
        ShoeConfig sc = shoe_defaults();
        StanceDetector shoe(sc, 1000.0);
        const DetectionScore b = detect(shoe, walk);
        CHECK(b.outputs == walk.t_ns.size());
        CHECK(b.latency_kept);
        CHECK(b.segments == truth);
        CHECK(b.agreement > 0.9);
    }
}

TEST_CASE("running: the adaptive SHOE detector finds every brief, rolling stance") {
    for (double rate : {100.0, 200.0, 400.0}) {
        CAPTURE(rate);
        // 0.12 s stances with a 1.2 rad/s heel-to-toe roll, violent swings.
        const Synthetic run = gait(rate, 0.12, 0.55, 9.80665, 15, 1.2, 2.5, 11);
        ShoeConfig sc = shoe_defaults();
        StanceDetector shoe(sc, 1000.0);
        const DetectionScore b = detect(shoe, run);
        CHECK(b.latency_kept);
        const int truth = segments_of(run.stance);
        CHECK(b.segments == truth);
        // The paper's detector with its printed thresholds misses them (|w| > 1 rad/s).
        MultiConditionConfig mc = multicondition_defaults();
        StanceDetector multi(mc, 1000.0);
        CHECK(detect(multi, run).segments < truth);
    }
}

TEST_CASE("SHOE statistic equals the direct sum over its window, with g given and with the window's |mean a|") {
    // 200 Hz walk on a sensor reading 0.97 g at rest. The detector keeps
    // running sums; the reference sums the window anew for every sample:
    // T = 1/n sum_j (|a_j - g u|^2 / sigma_a^2 + |w_j|^2 / sigma_w^2), u = mean a / |mean a|.
    const double g_read = 0.97 * 9.80665;
    const Synthetic walk = gait(200.0, 0.35, 0.65, g_read, 6, 0.3, 1.0, 5);
    double mean_still_given = 0, mean_still_own = 0;
    const ShoeConfig sc_default = shoe_defaults();
    for (double g : {0.0, 9.80665, 9.5}) {
        CAPTURE(g);
        ShoeConfig sc = shoe_defaults();
        sc.adaptive_window_s = 0.0;
        sc.gravity_mps2 = g;
        StanceDetector shoe(sc, 1000.0);
        std::vector<StanceDecision> out;
        const auto keep = [&](const StanceDecision& x) { out.push_back(x); };
        for (size_t k = 0; k < walk.t_ns.size(); ++k) shoe.push(walk.t_ns[k], walk.a[k].data(), walk.w[k].data(), keep);
        shoe.flush(keep);
        REQUIRE(out.size() == walk.t_ns.size());
        const int64_t h = static_cast<int64_t>(std::llround(sc.window_s * 0.5e9));
        double worst = 0, still_sum = 0;
        int compared = 0, still_n = 0;
        for (size_t k = 0; k < out.size(); ++k) {
            const int64_t t = walk.t_ns[k];
            if (t - h < walk.t_ns.front() || t + h > walk.t_ns.back()) continue;  // truncated windows
            Vec3 sum_a = Vec3::Zero();
            std::vector<size_t> in;
            for (size_t j = 0; j < walk.t_ns.size(); ++j)
                if (walk.t_ns[j] >= t - h && walk.t_ns[j] <= t + h) {
                    in.push_back(j);
                    sum_a += walk.a[j];
                }
            const double n = static_cast<double>(in.size());
            const Vec3 u = sum_a.normalized();
            const double gw = g > 0 ? g : sum_a.norm() / n;
            double T = 0;
            for (size_t j : in)
                T += (walk.a[j] - gw * u).squaredNorm() / (sc.accel_sd_mps2 * sc.accel_sd_mps2) +
                     walk.w[j].squaredNorm() / (sc.gyro_sd_radps * sc.gyro_sd_radps);
            T /= n;
            worst = std::max(worst, std::abs(out[k].statistic - T) / std::max(1.0, T));
            ++compared;
            if (t < 700000000) {  // the opening still period
                still_sum += T;
                ++still_n;
            }
        }
        CHECK(compared > 1000);
        CHECK(worst < 1e-9);
        if (g == 0.0) mean_still_own = still_sum / still_n;
        if (g == 9.80665) mean_still_given = still_sum / still_n;
    }
    // At rest the window's own |mean a| removes the 3 % scale error; a given
    // g leaves (0.03 g)^2 / sigma_a^2 in T (0.087 with sigma_a 1 m/s^2).
    CHECK(mean_still_own < 0.02);
    CHECK(mean_still_given - mean_still_own ==
          doctest::Approx(std::pow(g_read - 9.80665, 2) / (sc_default.accel_sd_mps2 * sc_default.accel_sd_mps2))
              .epsilon(0.05));
}

TEST_CASE("stance detector windows are in seconds: latency does not depend on the rate") {
    MultiConditionConfig mc = multicondition_defaults();
    mc.window_s = 0.2;
    mc.median_window_s = 0.1;
    mc.adaptive_window_s = 0.0;
    StanceDetector a(mc, 100.0), b(mc, 400.0);
    CHECK(a.latency_ns() == 150000000);
    CHECK(b.latency_ns() == 150000000);
    mc.adaptive_window_s = 1.0;
    StanceDetector c(mc, 250.0);
    CHECK(c.latency_ns() == 650000000);
    ShoeConfig sc = shoe_defaults();
    StanceDetector s(sc, 250.0);
    CHECK(s.latency_ns() == static_cast<int64_t>(std::llround((sc.window_s + sc.adaptive_window_s + sc.median_window_s) * 0.5e9)));
}
