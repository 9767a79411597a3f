#include "pednav_foot/stance_detector.hpp"

#include <algorithm>

namespace pednav::foot {

namespace {
int64_t half_ns(double window_s) { return static_cast<int64_t>(std::llround(window_s * 0.5e9)); }
}  // namespace

StanceDetector::StanceDetector(Kind kind, const StanceWindows& w, double max_rate_hz)
    : kind_(kind),
      stat_(half_ns(w.window_s), detail::capacity_for(w.window_s, max_rate_hz)),
      adapt_(half_ns(w.adaptive_window_s), detail::capacity_for(w.adaptive_window_s, max_rate_hz)),
      vote_(half_ns(w.median_window_s), detail::capacity_for(w.median_window_s, max_rate_hz)),
      adaptive_(w.adaptive_window_s > 0),
      adaptive_ratio_(w.adaptive_ratio),
      adaptive_max_(w.adaptive_max) {
    stat_.acc().is_shoe = kind == Kind::Shoe;
    adapt_.acc().init(detail::capacity_for(w.adaptive_window_s, max_rate_hz));
}

StanceDetector::StanceDetector(const MultiConditionConfig& c, double max_rate_hz)
    : StanceDetector(Kind::MultiCondition, c, max_rate_hz) {
    multi_ = c;
}

StanceDetector::StanceDetector(const ShoeConfig& c, double max_rate_hz) : StanceDetector(Kind::Shoe, c, max_rate_hz) {
    shoe_ = c;
}

bool StanceDetector::test(const detail::ImuElem& centre, double& statistic) const {
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
    const double ia = 1.0 / (shoe_.accel_sd_mps2 * shoe_.accel_sd_mps2);
    const double iw = 1.0 / (shoe_.gyro_sd_radps * shoe_.gyro_sd_radps);
    statistic = (sum_acc * ia + s.sw2 * iw) / n;
    return statistic < shoe_.threshold;
}

}  // namespace pednav::foot
