// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr_fusion/gnss_mode.hpp"

#include <stdexcept>

#include <pednav/pn_types.h>

namespace pednav::pdr_fusion {

GnssMode::GnssMode(const GnssModeConfig& c) : c_(c) {
    if (!(c.max_accuracy_m > 0) || !(c.good_accuracy_m > 0) || !(c.timeout_s > 0) || !(c.consistent_chi2 > 0))
        throw std::invalid_argument("GNSS mode: accuracies, timeout and chi2 must be > 0");
}

bool GnssMode::usable(double h_accuracy_m, int satellites, int fix_type) const {
    if (!(h_accuracy_m > 0) || h_accuracy_m > c_.max_accuracy_m) return false;
    if (satellites > 0 && satellites < c_.min_satellites) return false;
    return fix_type != PN_GNSS_FIX_DEAD_RECKONING;
}

FixQuality GnssMode::judge(int64_t t_ns, bool accepted, double h_accuracy_m, int satellites, double nis) {
    if (!accepted) return FixQuality::unusable;
    has_fix_ = true;
    t_last_used_ns_ = t_ns;
    const bool good = may_be_good(h_accuracy_m, satellites) && nis <= c_.consistent_chi2;
    last_ = good ? FixQuality::good : FixQuality::fused;
    return last_;
}

PositionMode GnssMode::mode(int64_t t_ns) const {
    if (!has_fix_ || static_cast<double>(t_ns - t_last_used_ns_) * 1e-9 > c_.timeout_s) return PositionMode::steps;
    return last_ == FixQuality::good ? PositionMode::gnss : PositionMode::fused;
}

}  // namespace pednav::pdr_fusion
