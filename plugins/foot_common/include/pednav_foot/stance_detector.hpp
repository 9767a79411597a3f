// Foot stance (zero-velocity) detectors with windows in seconds, O(1) per
// sample, no allocation after construction.
//
// Both detectors are two centred-window stages:
//   1. a per-sample test statistic over a centred window of window_s, turned
//      into a 0/1 stance decision;
//   2. a majority (binary median) filter over a centred window of
//      median_window_s.
// The decision about the sample at t is known once input up to
// t + window_s/2 + median_window_s/2 has arrived: that is latency_ns().
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "centred_window.hpp"

namespace pednav::foot {

struct StanceDecision {
    int64_t t_ns;     // time of the classified IMU sample
    bool stance;      // after the majority filter
    double statistic; // stage-1 statistic of that sample
};

// foot-imu-zupt-zaru-ekf sec. 2.3, eq. (16)-(23), windows in seconds.
// The windows both detectors share: a centred window for the statistic, an
// optional adaptive threshold over a longer centred window, a majority filter.
struct StanceWindows {
    double window_s;           // centred window of the statistic
    double median_window_s;    // majority filter
    double adaptive_window_s;  // centred window of the running minimum; 0 = fixed threshold only
    double adaptive_ratio;     // also stance when the statistic <= ratio x that minimum...
    double adaptive_max;       // ...and below this
};

struct MultiConditionConfig : StanceWindows {
    double accel_min_mps2 = 9.0;        // C1 lower bound on |a|, eq. (17)
    double accel_max_mps2 = 11.0;       // C1 upper bound on |a|
    double accel_std_max_mps2 = 0.5;    // C2: std of |a| over the window below this, eq. (20)
    double gyro_max_radps = 1.0;        // C3: |w| below this, eq. (22)
    // Window of eq. (18)-(19) 0.15 s (paper: 31 samples at 100 Hz), majority
    // filter 0.11 s (paper: 11 samples at 100 Hz). The adaptive threshold is
    // off (the paper's fixed conditions only); when on, it works as for SHOE
    // on the statistic max(std|a| / accel_std_max, |w| / gyro_max).
    MultiConditionConfig() : StanceWindows{0.15, 0.11, 0.0, 2.0, 4.0} {}
};

// SHOE / GLRT detector (Skog, Handel, Nilsson, Rantakokko 2010, eq. (10)):
// T = 1/W sum_j ( |a_j - g u|^2 / sigma_a^2 + |w_j|^2 / sigma_w^2 ), with
// u the mean specific force direction over the window; stance when T < gamma.
// With gravity_mps2 = 0 the window's own mean |a| replaces g, which makes the
// test blind to accelerometer scale errors (a sensor reading 0.97 g at rest).
//
// Adaptive threshold (adaptive_window_s > 0): a gait cycle holds one stance,
// and in brisk walking or running it is short and far from still. A sample is
// also stance when T is within a factor adaptive_ratio of the smallest T in a
// centred window of adaptive_window_s (longer than one gait cycle) and below
// adaptive_max; the running minimum is a monotone deque, O(1) amortised.
struct ShoeConfig : StanceWindows {
    double accel_sd_mps2 = 1.0;      // sigma_a
    double gyro_sd_radps = 0.5;      // sigma_w
    double threshold = 0.5;          // gamma (dimensionless, W-normalised)
    double gravity_mps2 = 0.0;       // g; 0 = the window's mean |a|
    // W = 0.06 s, majority filter 0.05 s, adaptive threshold over 1 s.
    ShoeConfig() : StanceWindows{0.06, 0.05, 1.0, 3.0, 60.0} {}
};

namespace detail {

struct ImuElem {
    int64_t t_ns;
    double a[3];
    double w2;   // |w|^2
    double am;   // |a| - 9.81 (offset keeps the running sums well conditioned)
};

struct MultiAcc {
    double s1 = 0, s2 = 0;
    double n = 0;
    void add(const ImuElem& e) { s1 += e.am; s2 += e.am * e.am; n += 1; }
    void remove(const ImuElem& e) { s1 -= e.am; s2 -= e.am * e.am; n -= 1; }
    void reset() { *this = MultiAcc{}; }
};

struct ShoeAcc {
    double sa[3] = {0, 0, 0};
    double sa2 = 0, sw2 = 0, n = 0;
    void add(const ImuElem& e) {
        for (int i = 0; i < 3; ++i) sa[i] += e.a[i];
        sa2 += e.a[0] * e.a[0] + e.a[1] * e.a[1] + e.a[2] * e.a[2];
        sw2 += e.w2;
        n += 1;
    }
    void remove(const ImuElem& e) {
        for (int i = 0; i < 3; ++i) sa[i] -= e.a[i];
        sa2 -= e.a[0] * e.a[0] + e.a[1] * e.a[1] + e.a[2] * e.a[2];
        sw2 -= e.w2;
        n -= 1;
    }
    void reset() { *this = ShoeAcc{}; }
};

struct StatElem {
    int64_t t_ns;
    double statistic;
    uint64_t seq;
    bool fixed;  // the fixed-threshold decision
};
// Sliding minimum of StatElem::statistic: monotone deque in a ring.
struct MinAcc {
    std::vector<StatElem> dq;
    size_t mask = 0, head = 0, tail = 0;  // [head, tail)
    void init(size_t capacity) {
        size_t cap = 16;
        while (cap < capacity) cap <<= 1;
        dq.resize(cap);
        mask = cap - 1;
    }
    void add(const StatElem& e) {
        while (tail > head && dq[(tail - 1) & mask].statistic >= e.statistic) --tail;
        dq[tail++ & mask] = e;
    }
    void remove(const StatElem& e) {
        if (tail > head && dq[head & mask].seq == e.seq) ++head;
    }
    void reset() { head = tail = 0; }
    double min() const { return tail > head ? dq[head & mask].statistic : HUGE_VAL; }
};

struct VoteElem {
    int64_t t_ns;
    double statistic;
    bool stance;
};
struct VoteAcc {
    int ones = 0, n = 0;
    void add(const VoteElem& e) { ones += e.stance ? 1 : 0; ++n; }
    void remove(const VoteElem& e) { ones -= e.stance ? 1 : 0; --n; }
    void reset() { *this = VoteAcc{}; }
};

inline size_t capacity_for(double window_s, double rate_hz) {
    return static_cast<size_t>(std::ceil(window_s * rate_hz)) + 64;
}

}  // namespace detail

// Ring capacities are sized for max_rate_hz (samples per second the detector
// can take without shrinking its windows).
class StanceDetector {
public:
    enum class Kind { MultiCondition, Shoe };

    StanceDetector(const MultiConditionConfig& c, double max_rate_hz);
    StanceDetector(const ShoeConfig& c, double max_rate_hz);

    int64_t latency_ns() const { return stat_.half_ns() + adapt_.half_ns() + vote_.half_ns(); }

    // Feeds one IMU sample (SI, sensor axes); calls out(const StanceDecision&)
    // for each sample whose decision became final.
    template <class Out>
    void push(int64_t t_ns, const double accel_mps2[3], const double gyro_radps[3], Out&& out) {
        detail::ImuElem e;
        e.t_ns = t_ns;
        e.a[0] = accel_mps2[0];
        e.a[1] = accel_mps2[1];
        e.a[2] = accel_mps2[2];
        e.w2 = gyro_radps[0] * gyro_radps[0] + gyro_radps[1] * gyro_radps[1] + gyro_radps[2] * gyro_radps[2];
        e.am = std::sqrt(e.a[0] * e.a[0] + e.a[1] * e.a[1] + e.a[2] * e.a[2]) - 9.81;
        stat_.push(e, [&](const detail::ImuElem& c, const StatAcc& acc) { vote(c, acc, out); });
        // Every stage-1 result up to t - h1 is out: later stages may finish
        // their centres against that watermark.
        int64_t mark = t_ns - stat_.half_ns();
        if (adaptive_) {
            adapt_.advance(mark, [&](const detail::StatElem& x, const detail::MinAcc& m) { adapt(x, m, out); });
            mark -= adapt_.half_ns();
        }
        vote_.advance(mark, [&](const detail::VoteElem& v, const detail::VoteAcc& a) { decide(v, a, out); });
    }

    template <class Out>
    void flush(Out&& out) {
        stat_.flush([&](const detail::ImuElem& c, const StatAcc& acc) { vote(c, acc, out); });
        adapt_.flush([&](const detail::StatElem& e, const detail::MinAcc& m) { adapt(e, m, out); });
        vote_.flush([&](const detail::VoteElem& v, const detail::VoteAcc& a) { decide(v, a, out); });
    }

    // Stage-1 decision and statistic for one centre (exposed for tests).
    bool test(const detail::ImuElem& centre, double& statistic) const;

private:
    StanceDetector(Kind kind, const StanceWindows& windows, double max_rate_hz);
    struct StatAcc {
        detail::MultiAcc multi;
        detail::ShoeAcc shoe;
        bool is_shoe = false;
        void add(const detail::ImuElem& e) { is_shoe ? shoe.add(e) : multi.add(e); }
        void remove(const detail::ImuElem& e) { is_shoe ? shoe.remove(e) : multi.remove(e); }
        void reset() { multi.reset(); shoe.reset(); }
    };

    template <class Out>
    void vote(const detail::ImuElem& c, const StatAcc& acc, Out& out) {
        acc_view_ = &acc;
        detail::VoteElem v;
        v.t_ns = c.t_ns;
        v.stance = test(c, v.statistic);
        if (!adaptive_) {
            vote_.push(v, [&](const detail::VoteElem& e, const detail::VoteAcc& a) { decide(e, a, out); });
            return;
        }
        adapt_.push(detail::StatElem{c.t_ns, v.statistic, seq_++, v.stance},
                    [&](const detail::StatElem& e, const detail::MinAcc& m) { adapt(e, m, out); });
    }

    template <class Out>
    void adapt(const detail::StatElem& e, const detail::MinAcc& m, Out& out) {
        detail::VoteElem v;
        v.t_ns = e.t_ns;
        v.statistic = e.statistic;
        v.stance = e.fixed || (e.statistic < adaptive_max_ && e.statistic <= adaptive_ratio_ * m.min());
        vote_.push(v, [&](const detail::VoteElem& x, const detail::VoteAcc& a) { decide(x, a, out); });
    }

    template <class Out>
    static void decide(const detail::VoteElem& e, const detail::VoteAcc& a, Out& out) {
        bool s = e.stance;
        if (2 * a.ones > a.n) s = true;
        else if (2 * a.ones < a.n) s = false;
        out(StanceDecision{e.t_ns, s, e.statistic});
    }

    Kind kind_;
    MultiConditionConfig multi_{};
    ShoeConfig shoe_{};
    CentredWindow<detail::ImuElem, StatAcc> stat_;
    CentredWindow<detail::StatElem, detail::MinAcc> adapt_;
    CentredWindow<detail::VoteElem, detail::VoteAcc> vote_;
    bool adaptive_ = false;
    double adaptive_ratio_ = 0, adaptive_max_ = 0;
    uint64_t seq_ = 0;
    const StatAcc* acc_view_ = nullptr;
    double shoe_ia_ = 0, shoe_iw_ = 0;  // 1 / sigma_a^2, 1 / sigma_w^2
};

inline bool StanceDetector::test(const detail::ImuElem& centre, double& statistic) const {
    const StatAcc& acc = *acc_view_;
    if (kind_ == Kind::MultiCondition) {
        const detail::MultiAcc& m = acc.multi;
        // foot-imu-zupt-zaru-ekf eq. (18)-(19): mean and variance of |a| over the window.
        const double mean = m.s1 / m.n;
        const double var = std::max(0.0, m.s2 / m.n - mean * mean);
        const double sd = std::sqrt(var);
        const double a_norm = centre.am + 9.81;
        const bool c1 = a_norm > multi_.accel_min_mps2 && a_norm < multi_.accel_max_mps2;  // eq. (17)
        const bool c2 = sd < multi_.accel_std_max_mps2;                                     // eq. (20)
        const bool c3 = centre.w2 < multi_.gyro_max_radps * multi_.gyro_max_radps;         // eq. (22)
        // C2 and C3 as one margin (< 1 when both hold), for plots and the adaptive stage.
        statistic = std::max(sd / multi_.accel_std_max_mps2, std::sqrt(centre.w2) / multi_.gyro_max_radps);
        return c1 && c2 && c3;                                                               // eq. (23)
    }
    const detail::ShoeAcc& s = acc.shoe;
    const double n = s.n;
    const double mean_norm = std::sqrt(s.sa[0] * s.sa[0] + s.sa[1] * s.sa[1] + s.sa[2] * s.sa[2]) / n;
    const double g = shoe_.gravity_mps2 > 0 ? shoe_.gravity_mps2 : mean_norm;
    // sum_j |a_j - g u|^2 = sum |a_j|^2 - 2 g n |mean a| + n g^2, with u = mean a / |mean a|.
    const double sum_acc = std::max(0.0, s.sa2 - 2.0 * g * n * mean_norm + n * g * g);
    statistic = (sum_acc * shoe_ia_ + s.sw2 * shoe_iw_) / n;
    return statistic < shoe_.threshold;
}

}  // namespace pednav::foot
