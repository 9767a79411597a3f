// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr/step_vector.hpp"

#include <algorithm>
#include <cstddef>

namespace pednav::pdr {

PlaneVector double_integral(const HorizontalSample* s, size_t n, bool remove_mean) {
    PlaneVector d;
    if (n < 2) return d;
    double me = 0.0, mn = 0.0;
    const double span_s = static_cast<double>(s[n - 1].t_ns - s[0].t_ns) * 1e-9;
    if (remove_mean && span_s > 0) {
        for (size_t k = 1; k < n; ++k) {
            const double dt = static_cast<double>(s[k].t_ns - s[k - 1].t_ns) * 1e-9;
            me += 0.5 * (s[k].east_mps2 + s[k - 1].east_mps2) * dt;
            mn += 0.5 * (s[k].north_mps2 + s[k - 1].north_mps2) * dt;
        }
        me /= span_s;
        mn /= span_s;
    }
    double ve = 0.0, vn = 0.0;
    for (size_t k = 1; k < n; ++k) {
        const double dt = static_cast<double>(s[k].t_ns - s[k - 1].t_ns) * 1e-9;
        const double ve1 = ve + (0.5 * (s[k].east_mps2 + s[k - 1].east_mps2) - me) * dt;
        const double vn1 = vn + (0.5 * (s[k].north_mps2 + s[k - 1].north_mps2) - mn) * dt;
        d.east_m += 0.5 * (ve + ve1) * dt;
        d.north_m += 0.5 * (vn + vn1) * dt;
        ve = ve1, vn = vn1;
    }
    return d;
}

StepVectorBuffer::StepVectorBuffer(double max_span_s)
    : max_span_ns_(static_cast<int64_t>(std::max(max_span_s, 0.01) * 1e9)) {
    samples_.reserve(1024);
}

void StepVectorBuffer::add(const HorizontalSample& s) {
    while (first_ < samples_.size() && samples_[first_].t_ns < s.t_ns - max_span_ns_) ++first_;
    if (first_ > 0 && first_ * 2 >= samples_.size()) {  // drop the old prefix, amortised O(1)
        samples_.erase(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(first_));
        first_ = 0;
    }
    samples_.push_back(s);
}

PlaneVector StepVectorBuffer::close(int64_t t_start_ns, int64_t t_end_ns, bool remove_mean) {
    const auto begin = samples_.begin() + static_cast<std::ptrdiff_t>(first_);
    const auto first = std::lower_bound(begin, samples_.end(), t_start_ns,
                                        [](const HorizontalSample& a, int64_t t) { return a.t_ns < t; });
    const auto end = std::upper_bound(begin, samples_.end(), t_end_ns,
                                      [](int64_t t, const HorizontalSample& a) { return t < a.t_ns; });
    PlaneVector d;
    if (first < end) d = double_integral(&*first, static_cast<size_t>(end - first), remove_mean);
    // The step's last sample is the next step's first.
    if (end > begin) first_ = static_cast<size_t>(end - 1 - samples_.begin());
    return d;
}

}  // namespace pednav::pdr
