// SPDX-License-Identifier: Apache-2.0
// The waist paper's three positioning modes (sec. 2.2): GNSS alone when the
// signal is good, fused (the EKF of GNSS and steps) when fixes come but are
// not reliable, steps alone when there are none. A fix is
//   unusable  when its accuracy is worse than max_accuracy_m, it has fewer
//             than min_satellites (when known), it is a dead-reckoning fix,
//             or the innovation gate rejects it (inconsistent with the steps);
//   good      when it is used, its accuracy is at most good_accuracy_m, it
//             has good_satellites or more (when known) and its normalised
//             innovation is at most consistent_chi2 (it agrees with the steps);
//   fused     otherwise.
// The mode is that of the last used fix while it is at most timeout_s old,
// and steps alone after that.
#pragma once

#include <cstdint>

namespace pednav::pdr_fusion {

enum class PositionMode { steps, fused, gnss };
enum class FixQuality { unusable, fused, good };

struct GnssModeConfig {
    double max_accuracy_m;    // worse fixes are not used
    int min_satellites;       // fewer (when known) are not used
    double good_accuracy_m;   // GNSS alone needs at most this
    int good_satellites;      // and at least this many (when known)
    double consistent_chi2;   // and this normalised innovation at most
    double timeout_s;         // steps alone this long after the last used fix
};

template <class Params>
GnssModeConfig gnss_mode_config(Params& p) {
    GnssModeConfig c;
    c.max_accuracy_m = p.number("gnss_max_accuracy_m");
    c.min_satellites = static_cast<int>(p.integer("gnss_min_satellites"));
    c.good_accuracy_m = p.number("gnss_good_accuracy_m");
    c.good_satellites = static_cast<int>(p.integer("gnss_good_satellites"));
    c.consistent_chi2 = p.number("gnss_consistent_chi2");
    c.timeout_s = p.number("gnss_timeout_s");
    return c;
}

class GnssMode {
public:
    explicit GnssMode(const GnssModeConfig& config);

    // Before the fix goes to the filter: may it be used at all?
    bool usable(double h_accuracy_m, int satellites, int fix_type) const;
    // Whether a fix may be good by its accuracy and satellites alone.
    bool may_be_good(double h_accuracy_m, int satellites) const {
        return h_accuracy_m <= c_.good_accuracy_m && (satellites == 0 || satellites >= c_.good_satellites);
    }
    // After the filter's gate: its quality, which sets the mode.
    FixQuality judge(int64_t t_ns, bool accepted, double h_accuracy_m, int satellites, double nis);
    // The mode at time t.
    PositionMode mode(int64_t t_ns) const;

private:
    GnssModeConfig c_;
    bool has_fix_ = false;
    int64_t t_last_used_ns_ = 0;
    FixQuality last_ = FixQuality::unusable;
};

}  // namespace pednav::pdr_fusion
