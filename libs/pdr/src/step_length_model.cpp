// SPDX-License-Identifier: Apache-2.0
#include "pednav_pdr/step_length_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pednav::pdr {

double step_length_m(const StepLengthModel& m, double accel_range_mps2) {
    const double r = std::max(0.0, accel_range_mps2);
    return std::max(0.0, m.k * std::pow(r, 1.0 / m.b) + m.beta_m);
}

StepLengthModel step_length_model_for_height(double height_m, double step_to_height, double typical_range_mps2,
                                             double b) {
    if (!(height_m > 0) || !(step_to_height > 0) || !(typical_range_mps2 > 0) || !(b > 0))
        throw std::invalid_argument("step length model: height, ratio, typical range and root must be positive");
    return {step_to_height * height_m / std::pow(typical_range_mps2, 1.0 / b), b, 0.0};
}

namespace {

void check_walks(const std::vector<CalibrationWalk>& walks) {
    if (walks.empty()) throw std::invalid_argument("step length fit: no walk");
    for (size_t i = 0; i < walks.size(); ++i) {
        if (walks[i].accel_ranges_mps2.empty())
            throw std::invalid_argument("step length fit: walk " + std::to_string(i) + " has no step");
        if (!(walks[i].distance_m > 0))
            throw std::invalid_argument("step length fit: walk " + std::to_string(i) + " has no positive distance");
    }
}

double rms_relative(const std::vector<CalibrationWalk>& walks, const StepLengthModel& m) {
    double s = 0;
    for (const CalibrationWalk& w : walks) {
        double d = 0;
        for (double r : w.accel_ranges_mps2) d += step_length_m(m, r);
        const double e = (d - w.distance_m) / w.distance_m;
        s += e * e;
    }
    return std::sqrt(s / static_cast<double>(walks.size()));
}

}  // namespace

// Walk w predicts k S_w + beta n_w for distance D_w, with S_w = sum r^(1/b)
// and n_w its steps. Relative residuals (k S_w + beta n_w - D_w) / D_w weigh
// short and long walks alike: with x_w = S_w / D_w, y_w = n_w / D_w the
// normal equations are those of fitting 1 = k x_w + beta y_w.
StepLengthFit fit_step_length(const std::vector<CalibrationWalk>& walks, double b, bool fit_beta, double beta_m) {
    check_walks(walks);
    if (!(b > 0)) throw std::invalid_argument("step length fit: the root b must be positive");
    double sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, sx_fixed = 0;
    for (const CalibrationWalk& w : walks) {
        double S = 0;
        for (double r : w.accel_ranges_mps2) S += std::pow(std::max(0.0, r), 1.0 / b);
        const double x = S / w.distance_m, y = static_cast<double>(w.accel_ranges_mps2.size()) / w.distance_m;
        sxx += x * x, sxy += x * y, syy += y * y, sx += x, sy += y;
        sx_fixed += x * (1.0 - beta_m * y);
    }
    StepLengthModel m{0.0, b, beta_m};
    const double det = sxx * syy - sxy * sxy;
    if (fit_beta && walks.size() >= 2 && det > 1e-9 * sxx * syy) {
        m.k = (sx * syy - sy * sxy) / det;
        m.beta_m = (sy * sxx - sx * sxy) / det;
    } else {
        m.k = sxx > 0 ? sx_fixed / sxx : 0.0;
    }
    return {m, rms_relative(walks, m), static_cast<int>(walks.size())};
}

StepLengthFit fit_step_length_and_root(const std::vector<CalibrationWalk>& walks, double b_min, double b_max,
                                       bool fit_beta, double beta_m) {
    if (!(b_min > 0) || !(b_max >= b_min)) throw std::invalid_argument("step length fit: bad range for the root b");
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = b_min, hi = b_max;
    double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
    StepLengthFit f1 = fit_step_length(walks, x1, fit_beta, beta_m), f2 = fit_step_length(walks, x2, fit_beta, beta_m);
    for (int i = 0; i < 40 && hi - lo > 1e-3; ++i) {
        if (f1.rms_relative_error <= f2.rms_relative_error) {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - phi * (hi - lo);
            f1 = fit_step_length(walks, x1, fit_beta, beta_m);
        } else {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + phi * (hi - lo);
            f2 = fit_step_length(walks, x2, fit_beta, beta_m);
        }
    }
    return f1.rms_relative_error <= f2.rms_relative_error ? f1 : f2;
}

std::vector<double> fit_linear_step_model(const std::vector<LinearCalibrationWalk>& walks) {
    if (walks.empty()) throw std::invalid_argument("step length fit: no walk");
    const size_t m = walks.front().basis_sums.size();
    if (m == 0) throw std::invalid_argument("step length fit: no constant to fit");
    // Normal equations of 1 = sum_j c_j x_wj, x_wj = G_wj / D_w.
    std::vector<double> A(m * m, 0.0), rhs(m, 0.0);
    for (size_t w = 0; w < walks.size(); ++w) {
        if (walks[w].basis_sums.size() != m)
            throw std::invalid_argument("step length fit: walk " + std::to_string(w) + " has another basis");
        if (!(walks[w].distance_m > 0))
            throw std::invalid_argument("step length fit: walk " + std::to_string(w) + " has no positive distance");
        for (size_t i = 0; i < m; ++i) {
            const double xi = walks[w].basis_sums[i] / walks[w].distance_m;
            rhs[i] += xi;
            for (size_t j = 0; j < m; ++j) A[i * m + j] += xi * walks[w].basis_sums[j] / walks[w].distance_m;
        }
    }
    // Gaussian elimination with partial pivoting (m is 1 to 3).
    double scale = 0.0;
    for (size_t i = 0; i < m; ++i) scale = std::max(scale, std::abs(A[i * m + i]));
    for (size_t col = 0; col < m; ++col) {
        size_t pivot = col;
        for (size_t r = col + 1; r < m; ++r)
            if (std::abs(A[r * m + col]) > std::abs(A[pivot * m + col])) pivot = r;
        if (!(std::abs(A[pivot * m + col]) > 1e-12 * scale))
            throw std::invalid_argument("step length fit: the walks do not determine the constants");
        if (pivot != col) {
            for (size_t j = 0; j < m; ++j) std::swap(A[col * m + j], A[pivot * m + j]);
            std::swap(rhs[col], rhs[pivot]);
        }
        for (size_t r = col + 1; r < m; ++r) {
            const double f = A[r * m + col] / A[col * m + col];
            for (size_t j = col; j < m; ++j) A[r * m + j] -= f * A[col * m + j];
            rhs[r] -= f * rhs[col];
        }
    }
    std::vector<double> c(m, 0.0);
    for (size_t i = m; i-- > 0;) {
        double v = rhs[i];
        for (size_t j = i + 1; j < m; ++j) v -= A[i * m + j] * c[j];
        c[i] = v / A[i * m + i];
    }
    return c;
}

}  // namespace pednav::pdr
