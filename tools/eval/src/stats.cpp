// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <numeric>

#include <pednav_eval/metrics.hpp>

namespace pednav::eval {

double percentile(std::vector<double> v, double q, PercentileMethod method) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const double rank = (static_cast<double>(v.size()) - 1.0) * std::clamp(q, 0.0, 100.0) / 100.0;
    if (method == PercentileMethod::higher) return v[static_cast<size_t>(std::ceil(rank))];
    const size_t lo = static_cast<size_t>(std::floor(rank));
    const size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (rank - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

double standard_deviation(const std::vector<double>& v, size_t ddof) {
    if (v.size() <= ddof) return NAN;
    const double mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    double s = 0.0;
    for (double x : v) s += (x - mean) * (x - mean);
    return std::sqrt(s / static_cast<double>(v.size() - ddof));
}

AxisStats axis_stats(const std::vector<double>& v, size_t ddof) {
    AxisStats a;
    if (v.empty()) return a;
    a.min = *std::min_element(v.begin(), v.end());
    a.max = *std::max_element(v.begin(), v.end());
    a.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    a.sd = standard_deviation(v, ddof);
    return a;
}

ErrorStats error_stats(const std::vector<double>& v) {
    ErrorStats e;
    e.n = v.size();
    if (v.empty()) return e;
    e.mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
    e.median = percentile(v, 50.0);
    e.p75 = percentile(v, 75.0);
    e.sd = standard_deviation(v);
    e.max = *std::max_element(v.begin(), v.end());
    double ss = 0.0;
    for (double x : v) ss += x * x;
    e.rms = std::sqrt(ss / static_cast<double>(v.size()));
    return e;
}

double angle_diff_deg(double a, double b) {
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d <= -180.0) d += 360.0;
    return d;
}

double ipin_score(const std::vector<double>& horizontal_m, const std::vector<int>& floor_diff) {
    std::vector<double> e(horizontal_m.size());
    for (size_t i = 0; i < e.size(); ++i)
        e[i] = horizontal_m[i] + 15.0 * (i < floor_diff.size() ? std::abs(floor_diff[i]) : 0);
    return percentile(e, 75.0);
}

double loop_closure_pct(double closure_m, double distance_m) {
    return distance_m > 0.0 ? 100.0 * closure_m / distance_m : NAN;
}

}  // namespace pednav::eval
