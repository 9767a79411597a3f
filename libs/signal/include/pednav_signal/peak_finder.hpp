// SPDX-License-Identifier: Apache-2.0
// Peaks of a time-stamped signal, one at a time as they are confirmed:
//  - a peak is a local maximum at least min_height high;
//  - after a peak, a refractory interval of min_interval_s in which no new
//    peak may start (the double bump of one heel strike is one peak);
//  - a candidate is confirmed once the signal has fallen min_drop below it, or
//    confirm_s after it without a higher value, whichever comes first; so
//    every peak is reported at most confirm_s after its time (a fixed
//    look-ahead).
// With each peak comes the lowest value since the previous one (the valley
// between them), for the signal's range over the interval.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

namespace pednav::signal {

struct PeakFinderConfig {
    double min_interval_s;  // refractory time after a peak, s (>= 0)
    double min_height;      // a peak is at least this high (signal units)
    double min_drop;        // confirmed once the signal has fallen this far below it (> 0)
    double confirm_s;       // or this long after it without a higher value, s (> 0)
};

struct Peak {
    int64_t t_ns = 0;
    double value = 0.0;
    double valley = 0.0;  // lowest value between the previous peak (or the start) and this one
};

class PeakFinder {
public:
    explicit PeakFinder(const PeakFinderConfig& c) : c_(c) {}

    // One sample (t_ns increasing). True when a peak is confirmed with it: out.
    bool push(int64_t t_ns, double x, Peak& out) {
        bool found = false;
        if (has_candidate_ && (x <= candidate_.value - c_.min_drop ||
                               static_cast<double>(t_ns - candidate_.t_ns) * 1e-9 >= c_.confirm_s)) {
            out = candidate_;
            found = true;
            has_candidate_ = false;
            has_peak_ = true;
            last_peak_ns_ = candidate_.t_ns;
            valley_ = after_candidate_;
        }
        const bool refractory =
            has_peak_ && static_cast<double>(t_ns - last_peak_ns_) * 1e-9 < c_.min_interval_s;
        if (!refractory && x >= c_.min_height && (!has_candidate_ || x > candidate_.value)) {
            // The valley before it: up to the first candidate of this peak, and
            // between the candidates it replaces.
            before_candidate_ = has_candidate_ ? std::min(before_candidate_, after_candidate_) : valley_;
            has_candidate_ = true;
            candidate_.t_ns = t_ns;
            candidate_.value = x;
            candidate_.valley = before_candidate_;
            after_candidate_ = std::numeric_limits<double>::infinity();
        } else if (has_candidate_) {
            after_candidate_ = std::min(after_candidate_, x);
        }
        valley_ = std::min(valley_, x);
        return found;
    }

    // A candidate not yet confirmed (at the end of a stream).
    bool pending(Peak& out) const {
        if (has_candidate_) out = candidate_;
        return has_candidate_;
    }
    // Lowest value since the last peak (or the start).
    double valley() const { return valley_; }
    // Forget the valley so far (a pause was reported): the next peak's valley
    // is the lowest value from now on.
    void restart_valley(double x) { valley_ = x; }
    void reset() {
        has_candidate_ = has_peak_ = false;
        valley_ = before_candidate_ = after_candidate_ = std::numeric_limits<double>::infinity();
    }

private:
    PeakFinderConfig c_;
    bool has_candidate_ = false, has_peak_ = false;
    Peak candidate_;
    int64_t last_peak_ns_ = 0;
    double valley_ = std::numeric_limits<double>::infinity();
    double before_candidate_ = std::numeric_limits<double>::infinity();  // valley up to the candidate
    double after_candidate_ = std::numeric_limits<double>::infinity();   // lowest since the candidate
};

}  // namespace pednav::signal
