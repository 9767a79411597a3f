// SPDX-License-Identifier: Apache-2.0
// Foot stance (zero-velocity) detectors with windows in seconds, O(1) per
// sample, no allocation after construction.
//
// Both detectors are chains of time-centred windows:
//   1. a per-sample test statistic over a centred window of window_s, turned
//      into a 0/1 stance decision;
//   2. (optional) an adaptive threshold: the running minimum of the statistic
//      over a centred window of adaptive_window_s;
//   3. a majority (binary median) filter over a centred window of
//      median_window_s.
// The window of the sample at t_c holds every sample with |t - t_c| <= half
// the window; a stage finishes the centre t_c once its input has reached
// t_c + half (or the raw input has reached the sum of the half windows up to
// it: a watermark). The decision about the sample at t is known once input up
// to t + window_s/2 + adaptive_window_s/2 + median_window_s/2 has arrived:
// that is latency_ns().
//
// The three stages run as one pass per input sample over two rings (the raw
// samples of stage 1; the statistics and stage-2 decisions of stages 2 and 3,
// indexed by the same sample number), with their indices in the object and
// no callbacks between the stages. The windows, the running minimum and the
// majority vote are pednav_signal's (centred_window.hpp, running_minimum.hpp,
// majority_vote.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <type_traits>

#include <pednav_signal/centred_window.hpp>
#include <pednav_signal/majority_vote.hpp>
#include <pednav_signal/running_minimum.hpp>

namespace pednav::zupt_ins {

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
    double accel_min_mps2;        // C1 lower bound on |a|, eq. (17)
    double accel_max_mps2;       // C1 upper bound on |a|
    double accel_std_max_mps2;    // C2: std of |a| over the window below this, eq. (20)
    double gyro_max_radps;        // C3: |w| below this, eq. (22)
    // The paper's window of eq. (18)-(19) is 31 samples at 100 Hz, its
    // majority filter 11. When the adaptive threshold is on, it works as for
    // SHOE on the statistic max(std|a| / accel_std_max, |w| / gyro_max).
};

// SHOE / GLRT detector (Skog, Handel, Nilsson, Rantakokko 2010, eq. (10)):
// T = 1/W sum_j ( |a_j - g u|^2 / sigma_a^2 + |w_j|^2 / sigma_w^2 ), with
// u the mean specific force direction over the window; stance when T < gamma.
// With gravity_mps2 = 0 the window's own |mean a| replaces g, which makes the
// test blind to accelerometer scale errors (a sensor reading 0.97 g at rest).
//
// Adaptive threshold (adaptive_window_s > 0): a gait cycle holds one stance,
// and in brisk walking or running it is short and far from still. A sample is
// also stance when T is within a factor adaptive_ratio of the smallest T in a
// centred window of adaptive_window_s (longer than one gait cycle) and below
// adaptive_max; the running minimum is a monotone deque, O(1) amortised.
struct ShoeConfig : StanceWindows {
    double accel_sd_mps2;      // sigma_a
    double gyro_sd_radps;      // sigma_w
    double threshold;          // gamma (dimensionless, W-normalised)
    double gravity_mps2;       // g; 0 = the window's |mean a|
};

// No defaults in these configs: the stance plugins' parameter schemas hold
// them, with their ranges (pednav plugins --params). The configs from named
// values: `v.number(key)` for each field, by its name (a plugin's SDK Params;
// a test's values read from the schema).
template <class Values>
void read_stance_windows(Values& v, StanceWindows& w) {
    w.window_s = v.number("window_s");
    w.median_window_s = v.number("median_window_s");
    w.adaptive_window_s = v.number("adaptive_window_s");
    w.adaptive_ratio = v.number("adaptive_ratio");
    w.adaptive_max = v.number("adaptive_max");
}
template <class Values>
MultiConditionConfig multicondition_config(Values& v) {
    MultiConditionConfig c;
    c.accel_min_mps2 = v.number("accel_min_mps2");
    c.accel_max_mps2 = v.number("accel_max_mps2");
    c.accel_std_max_mps2 = v.number("accel_std_max_mps2");
    c.gyro_max_radps = v.number("gyro_max_radps");
    read_stance_windows(v, c);
    return c;
}
template <class Values>
ShoeConfig shoe_config(Values& v) {
    ShoeConfig c;
    c.accel_sd_mps2 = v.number("accel_sd_mps2");
    c.gyro_sd_radps = v.number("gyro_sd_radps");
    c.threshold = v.number("threshold");
    c.gravity_mps2 = v.number("gravity_mps2");
    read_stance_windows(v, c);
    return c;
}

// Ring capacities are sized for max_rate_hz (samples per second the detector
// can take without shrinking its windows). When the input comes faster, a
// full stage shrinks its windows from the left (finishing its oldest centre
// if needed).
class StanceDetector {
public:
    enum class Kind { MultiCondition, Shoe };

    StanceDetector(const MultiConditionConfig& c, double max_rate_hz);
    StanceDetector(const ShoeConfig& c, double max_rate_hz);

    int64_t latency_ns() const { return h1_ + h2_ + h3_; }

    // Feeds one IMU sample (SI, sensor axes); calls out(const StanceDecision&)
    // for each sample whose decision became final, in time order.
    template <class Out>
    void push(int64_t t_ns, const double accel_mps2[3], const double gyro_radps[3], Out&& out) {
        if (kind_ == Kind::Shoe) {
            if (adaptive_) push_impl<true, true>(t_ns, accel_mps2, gyro_radps, out);
            else push_impl<true, false>(t_ns, accel_mps2, gyro_radps, out);
        } else {
            if (adaptive_) push_impl<false, true>(t_ns, accel_mps2, gyro_radps, out);
            else push_impl<false, false>(t_ns, accel_mps2, gyro_radps, out);
        }
    }

    // End of stream: finishes every pending sample with truncated windows.
    template <class Out>
    void flush(Out&& out) {
        if (kind_ == Kind::Shoe) {
            if (adaptive_) flush_impl<true, true>(out);
            else flush_impl<true, false>(out);
        } else {
            if (adaptive_) flush_impl<false, true>(out);
            else flush_impl<false, false>(out);
        }
    }

private:
    StanceDetector(Kind kind, const StanceWindows& windows, double max_rate_hz);

    // Offset taken off |a| before the multi-condition running sums (keeps
    // them well conditioned) and added back for the C1 test.
    static constexpr double kAccelNormOffset = 9.81;

    // Stage-1 input: one raw sample (its time is in t1_). SHOE fills a, a2
    // and w2; the multi-condition detector am and w2.
    struct In {
        double a[3];
        double a2;  // |a|^2
        double w2;  // |w|^2
        double am;  // |a| - kAccelNormOffset
    };

    // ---- stage 1: running sums over the centred window -------------------
    struct ShoeSums {
        double a[3] = {0, 0, 0};
        double aa = 0, w2 = 0;
        void add(const In& e) {
            a[0] += e.a[0];
            a[1] += e.a[1];
            a[2] += e.a[2];
            aa += e.a2;
            w2 += e.w2;
        }
        void remove(const In& e) {
            a[0] -= e.a[0];
            a[1] -= e.a[1];
            a[2] -= e.a[2];
            aa -= e.a2;
            w2 -= e.w2;
        }
    };
    struct MultiSums {
        double m1 = 0, m2 = 0;
        void add(const In& e) {
            m1 += e.am;
            m2 += e.am * e.am;
        }
        void remove(const In& e) {
            m1 -= e.am;
            m2 -= e.am * e.am;
        }
    };
    template <bool Shoe>
    using Sums = std::conditional_t<Shoe, ShoeSums, MultiSums>;
    template <bool Shoe>
    Sums<Shoe>& sums() {
        if constexpr (Shoe) return shoe_sums_;
        else return multi_sums_;
    }

    // Recomputes the sums from the window contents, bounding the round-off
    // that add/remove pairs accumulate over a long stream.
    template <bool Shoe>
    void rebuild1() {
        since_rebuild_ = 0;
        Sums<Shoe> x{};
        for (uint64_t i = lo1_; i < hi1_; ++i) x.add(in_[i & mask1_]);
        sums<Shoe>() = x;
    }

    // Stage-1 statistic and fixed decision of `centre` from the sums over n samples.
    bool test(const MultiSums& m, const In& centre, double n, double& statistic) const {
        // foot-imu-zupt-zaru-ekf eq. (18)-(19): mean and variance of |a| over the window.
        const double mean = m.m1 / n;
        const double var = std::max(0.0, m.m2 / n - mean * mean);
        const double sd = std::sqrt(var);
        const double a_norm = centre.am + kAccelNormOffset;
        const bool c1 = a_norm > multi_.accel_min_mps2 && a_norm < multi_.accel_max_mps2;  // eq. (17)
        const bool c2 = sd < multi_.accel_std_max_mps2;                                     // eq. (20)
        const bool c3 = centre.w2 < multi_.gyro_max_radps * multi_.gyro_max_radps;         // eq. (22)
        // C2 and C3 as one margin (< 1 when both hold), for plots and the adaptive stage.
        statistic = std::max(sd / multi_.accel_std_max_mps2, std::sqrt(centre.w2) / multi_.gyro_max_radps);
        return c1 && c2 && c3;                                                               // eq. (23)
    }
    bool test(const ShoeSums& x, const In&, double n, double& statistic) const {
        // sum_j |a_j - g u|^2 = sum |a_j|^2 - 2 g n |mean a| + n g^2, with u = mean a / |mean a|;
        // with g = |mean a| (gravity_mps2 0) that is sum |a_j|^2 - |sum a|^2 / n, without the
        // square root. One division, 1/n, off the chain of the sums.
        const double inv_n = 1.0 / n;
        const double sum2 = x.a[0] * x.a[0] + x.a[1] * x.a[1] + x.a[2] * x.a[2];
        double sum_acc;
        if (shoe_.gravity_mps2 > 0) {
            const double g = shoe_.gravity_mps2;
            sum_acc = x.aa - 2.0 * g * std::sqrt(sum2) + n * g * g;
        } else {
            sum_acc = x.aa - sum2 * inv_n;
        }
        statistic = (std::max(0.0, sum_acc) * shoe_ia_ + x.w2 * shoe_iw_) * inv_n;
        return statistic < shoe_.threshold;
    }

    // Finishes the stage-1 centre c1_ and hands its result to the next stage.
    // The sums are updated in a local copy (the ring stores could alias them).
    template <bool Shoe, bool Adaptive, class Out>
    void emit1(Out& out) {
        const In* ring = in_.get();
        const int64_t* tr = t1_.get();
        const uint64_t mask = mask1_, n = n1_, c = c1_;
        const int64_t t = tr[c & mask];
        uint64_t hi = hi1_, lo = lo1_;
        Sums<Shoe> x = sums<Shoe>();
        signal::slide_centred_window(tr, mask, n, c, t, h1_, hi, lo, [&](uint64_t i) { x.add(ring[i & mask]); },
                                     [&](uint64_t i) { x.remove(ring[i & mask]); });
        hi1_ = hi;
        lo1_ = lo;
        c1_ = c + 1;
        sums<Shoe>() = x;
        if (++since_rebuild_ >= 8192) {
            rebuild1<Shoe>();
            x = sums<Shoe>();
        }
        double statistic;
        const bool fixed = test(x, ring[c & mask], static_cast<double>(hi - lo), statistic);
        if (Adaptive) push2(t, statistic, fixed, out);
        else push3_new(t, statistic, fixed, out);
    }

    // ---- stage 2: running minimum of the statistic ---------------------------
    template <class Out>
    void push2(int64_t t, double statistic, bool fixed, Out& out) {
        if (n2_ - lo2_ >= cap2_) make_room2(out);
        const uint64_t i = n2_ & maskd_;
        td_[i] = t;
        st_[i] = statistic;
        fx_[i] = fixed;
        const uint64_t n = ++n2_;
        while (c2_ < n && t >= td_[c2_ & maskd_] + h2_) emit2(out);
    }

    template <class Out>
    void emit2(Out& out) {
        const int64_t* tr = td_.get();
        const double* st = st_.get();
        const uint64_t c = c2_, n = n2_, mask = maskd_;
        const int64_t t = tr[c & mask];
        uint64_t hi = hi2_, lo = lo2_;
        signal::RunningMinimum minimum = minimum_;
        signal::slide_centred_window(
            tr, mask, n, c, t, h2_, hi, lo, [&](uint64_t i) { minimum.push(i, st, mask); },
            [&](uint64_t i) { minimum.pop(i); });
        hi2_ = hi;
        lo2_ = lo;
        minimum_.head = minimum.head;
        minimum_.tail = minimum.tail;
        c2_ = c + 1;
        // (The deque holds exactly the window's strict suffix minima whatever
        // the history: it needs no periodic rebuild.)
        const double s = st[c & mask];
        const double m = minimum.min(st, mask);
        const bool stance = fx_[c & mask] || (s < adaptive_max_ && s <= adaptive_ratio_ * m);
        push3(c, t, stance, out);
    }

    template <class Out>
    void make_room2(Out& out) {
        while (n2_ - lo2_ >= cap2_) {
            if (lo2_ < c2_ && lo2_ < hi2_) {
                minimum_.pop(lo2_);
                ++lo2_;
            } else {
                emit2(out);
            }
        }
    }

    // ---- stage 3: majority vote -------------------------------------------
    // Sample i at time t (its statistic already in the ring) enters the vote.
    template <class Out>
    void push3(uint64_t i, int64_t t, bool stance, Out& out) {
        if (n3_ - lo3_ >= cap3_) make_room3(out);
        sn_[i & maskd_] = stance;
        const uint64_t n = n3_ = i + 1;
        while (c3_ < n && t >= td_[c3_ & maskd_] + h3_) emit3(out);
    }
    // Without the adaptive stage: the stage-1 result goes straight to the vote.
    template <class Out>
    void push3_new(int64_t t, double statistic, bool fixed, Out& out) {
        if (n3_ - lo3_ >= cap3_) make_room3(out);
        const uint64_t i = n3_ & maskd_;
        td_[i] = t;
        st_[i] = statistic;
        fx_[i] = sn_[i] = fixed;
        const uint64_t n = ++n3_;
        while (c3_ < n && t >= td_[c3_ & maskd_] + h3_) emit3(out);
    }

    template <class Out>
    void emit3(Out& out) {
        const int64_t* tr = td_.get();
        const bool* sn = sn_.get();
        const uint64_t c = c3_, n = n3_, mask = maskd_;
        const int64_t t = tr[c & mask];
        uint64_t hi = hi3_, lo = lo3_;
        signal::MajorityVote vote = vote_;
        signal::slide_centred_window(tr, mask, n, c, t, h3_, hi, lo, [&](uint64_t i) { vote.add(sn[i & mask]); },
                                     [&](uint64_t i) { vote.remove(sn[i & mask]); });
        hi3_ = hi;
        lo3_ = lo;
        vote_ = vote;
        c3_ = c + 1;
        const bool s = vote.decide(static_cast<int64_t>(hi - lo), sn[c & mask]);
        out(StanceDecision{t, s, st_[c & mask]});
    }

    template <class Out>
    void make_room3(Out& out) {
        while (n3_ - lo3_ >= cap3_) {
            if (lo3_ < c3_ && lo3_ < hi3_) {
                vote_.remove(sn_[lo3_ & maskd_]);
                ++lo3_;
            } else {
                emit3(out);
            }
        }
    }

    // ---- the pass per sample ----------------------------------------------
    template <bool Shoe, bool Adaptive, class Out>
    void make_room1(Out& out) {
        while (n1_ - lo1_ >= cap1_) {
            if (lo1_ < c1_ && lo1_ < hi1_) {
                sums<Shoe>().remove(in_[lo1_ & mask1_]);
                ++lo1_;
            } else {
                emit1<Shoe, Adaptive>(out);
            }
        }
    }

    template <bool Shoe, bool Adaptive, class Out>
    void push_impl(int64_t t_ns, const double* a, const double* w, Out& out) {
        if (n1_ - lo1_ >= cap1_) make_room1<Shoe, Adaptive>(out);
        const uint64_t k = n1_ & mask1_;
        t1_[k] = t_ns;
        In& e = in_[k];
        const double a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
        e.w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        if constexpr (Shoe) {
            e.a[0] = a[0];
            e.a[1] = a[1];
            e.a[2] = a[2];
            e.a2 = a2;
        } else {
            e.am = std::sqrt(a2) - kAccelNormOffset;
        }
        const uint64_t n = ++n1_;
        while (c1_ < n && t_ns >= t1_[c1_ & mask1_] + h1_) emit1<Shoe, Adaptive>(out);
        // Every stage-1 result up to t - h1 is out: later stages may finish
        // their centres against that watermark.
        int64_t mark = t_ns - h1_;
        if (Adaptive) {
            while (c2_ < n2_ && td_[c2_ & maskd_] + h2_ <= mark) emit2(out);
            mark -= h2_;
        }
        while (c3_ < n3_ && td_[c3_ & maskd_] + h3_ <= mark) emit3(out);
    }

    template <bool Shoe, bool Adaptive, class Out>
    void flush_impl(Out& out) {
        while (c1_ < n1_) emit1<Shoe, Adaptive>(out);
        if (Adaptive)
            while (c2_ < n2_) emit2(out);
        while (c3_ < n3_) emit3(out);
    }

    Kind kind_;
    MultiConditionConfig multi_{};
    ShoeConfig shoe_{};
    bool adaptive_ = false;
    double adaptive_ratio_ = 0, adaptive_max_ = 0;
    double shoe_ia_ = 0, shoe_iw_ = 0;  // 1 / sigma_a^2, 1 / sigma_w^2
    int64_t h1_ = 0, h2_ = 0, h3_ = 0;  // half windows

    // Stage s holds the samples [lo_s, n_s), its running result covers
    // [lo_s, hi_s), its next centre is c_s.
    // Stage 1: a ring of raw samples.
    std::unique_ptr<int64_t[]> t1_;
    std::unique_ptr<In[]> in_;
    uint64_t cap1_ = 0, mask1_ = 0;
    uint64_t n1_ = 0, c1_ = 0, lo1_ = 0, hi1_ = 0;
    uint32_t since_rebuild_ = 0;
    ShoeSums shoe_sums_;
    MultiSums multi_sums_;

    // Stages 2 and 3 share one ring indexed by sample number: time,
    // statistic, fixed decision (stage 1), decision with the adaptive
    // threshold (stage 2).
    std::unique_ptr<int64_t[]> td_;
    std::unique_ptr<double[]> st_;
    std::unique_ptr<bool[]> fx_, sn_;
    uint64_t maskd_ = 0;
    uint64_t cap2_ = 0, n2_ = 0, c2_ = 0, lo2_ = 0, hi2_ = 0;
    std::unique_ptr<uint64_t[]> dq_;    // the running minimum's ring of sample numbers
    signal::RunningMinimum minimum_;  // over dq_
    uint64_t cap3_ = 0, n3_ = 0, c3_ = 0, lo3_ = 0, hi3_ = 0;
    signal::MajorityVote vote_;
};

}  // namespace pednav::zupt_ins
