// SPDX-License-Identifier: Apache-2.0
#include "spline.hpp"

#include <algorithm>
#include <stdexcept>

namespace pednav::sim::detail {

ClampedSpline::ClampedSpline(std::vector<double> t, std::vector<double> y)
    : t_(std::move(t)), y_(std::move(y)) {
    const size_t n = t_.size();
    if (n < 2 || y_.size() != n) throw std::runtime_error("spline: at least two knots");
    // Tridiagonal system for the second derivatives, end slopes zero.
    std::vector<double> a(n, 0.0), b(n, 0.0), c(n, 0.0), d(n, 0.0);
    for (size_t i = 0; i < n; ++i) {
        const double hl = i > 0 ? t_[i] - t_[i - 1] : 0.0;
        const double hr = i + 1 < n ? t_[i + 1] - t_[i] : 0.0;
        const double sl = i > 0 ? (y_[i] - y_[i - 1]) / hl : 0.0;  // slope 0 before the first knot
        const double sr = i + 1 < n ? (y_[i + 1] - y_[i]) / hr : 0.0;
        a[i] = hl / 6.0;
        b[i] = (hl + hr) / 3.0;
        c[i] = hr / 6.0;
        d[i] = sr - sl;
    }
    // Thomas algorithm.
    for (size_t i = 1; i < n; ++i) {
        const double w = a[i] / b[i - 1];
        b[i] -= w * c[i - 1];
        d[i] -= w * d[i - 1];
    }
    m_.assign(n, 0.0);
    m_[n - 1] = d[n - 1] / b[n - 1];
    for (size_t i = n - 1; i-- > 0;) m_[i] = (d[i] - c[i] * m_[i + 1]) / b[i];
}

Profile ClampedSpline::at(double t) const {
    if (t <= t_.front()) return {y_.front(), 0.0, 0.0};
    if (t >= t_.back()) return {y_.back(), 0.0, 0.0};
    const size_t i = static_cast<size_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin()) - 1;
    const double h = t_[i + 1] - t_[i];
    const double A = (t_[i + 1] - t) / h, B = (t - t_[i]) / h;
    const double f =
        A * y_[i] + B * y_[i + 1] + ((A * A * A - A) * m_[i] + (B * B * B - B) * m_[i + 1]) * h * h / 6.0;
    const double df =
        (y_[i + 1] - y_[i]) / h + (-(3.0 * A * A - 1.0) * m_[i] + (3.0 * B * B - 1.0) * m_[i + 1]) * h / 6.0;
    const double ddf = A * m_[i] + B * m_[i + 1];
    return {f, df, ddf};
}

}  // namespace pednav::sim::detail
