// SPDX-License-Identifier: Apache-2.0
// One scalar measurement of a Kalman filter whose measurement row has few
// nonzero entries, for filters that take a vector measurement with
// uncorrelated noise one component at a time: the posterior is the joint
// update's (each component's innovation is taken against the state as the
// components before it corrected it), at O(N^2) per component instead of
// the O(N^3) of the matrix form.
//
// Measurement y = h x + v, var v = r, h given by its nonzero entries
// (indices idx, values val). With c = P h^T, s = h c + r, K = c / s:
//   dx <- dx + K (y - h dx)
//   P  <- (I - K h) P (I - K h)^T + r K K^T = P - K c^T - c K^T + s K K^T
// (the Joseph form expanded for one row), evaluated on the upper triangle
// and mirrored: P stays exactly symmetric. dx accumulates the corrections
// of the components, y is each one's innovation against the state before
// the first (dx = 0 then).
#pragma once

#include <Eigen/Core>

namespace pednav::navmath {

// s = h P h^T + r: the innovation variance (the gate's denominator).
template <int N, int M>
double kalman_innovation_variance(const Eigen::Matrix<double, N, N>& P, const int (&idx)[M],
                                  const double (&val)[M], double r) {
    double s = r;
    for (int m = 0; m < M; ++m) {
        double c = 0.0;
        for (int k = 0; k < M; ++k) c += P(idx[m], idx[k]) * val[k];
        s += val[m] * c;
    }
    return s;
}

// The update above; returns s, or 0 (and changes nothing) when s is not
// positive.
template <int N, int M>
double kalman_scalar_update(Eigen::Matrix<double, N, N>& P, Eigen::Matrix<double, N, 1>& dx,
                            const int (&idx)[M], const double (&val)[M], double y, double r) {
    double c[N];
    for (int i = 0; i < N; ++i) c[i] = 0.0;
    for (int m = 0; m < M; ++m) {
        const double v = val[m];
        for (int i = 0; i < N; ++i) c[i] += P(i, idx[m]) * v;  // a column of P: contiguous
    }
    double s = r, innovation = y;
    for (int m = 0; m < M; ++m) {
        s += val[m] * c[idx[m]];
        innovation -= val[m] * dx(idx[m]);
    }
    if (!(s > 0)) return 0.0;
    double K[N];
    const double inv = 1.0 / s;
    for (int i = 0; i < N; ++i) {
        K[i] = c[i] * inv;
        dx(i) += K[i] * innovation;
    }
    for (int b = 0; b < N; ++b) {
        const double kb = K[b], cb = c[b], skb = s * kb;
        for (int a = 0; a <= b; ++a) {
            const double v = P(a, b) + (skb * K[a] - (K[a] * cb + c[a] * kb));
            P(a, b) = v;
            P(b, a) = v;
        }
    }
    return s;
}

}  // namespace pednav::navmath
