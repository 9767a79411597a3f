// SPDX-License-Identifier: Apache-2.0
#include "record_checks.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <limits>

namespace pednav::engine {

const char* record_type_name(pn_record_type_t type) {
    switch (type) {
        case PN_REC_IMU: return "imu";
        case PN_REC_MAG: return "mag";
        case PN_REC_BARO: return "baro";
        case PN_REC_GNSS: return "gnss";
        case PN_REC_GAIT_PHASE: return "gait_phase";
        case PN_REC_STEP: return "step";
        case PN_REC_ATTITUDE: return "attitude";
        case PN_REC_ATTITUDE_CORRECTION: return "attitude_correction";
        case PN_REC_POSITION: return "position";
        case PN_REC_STRIDE: return "stride";
        default: return "unknown";
    }
}

namespace {

// The one definition of what a record must satisfy. Each check returns true
// when its values are fine, so a record's checks chain with &&. Instantiated
// twice: Checker<false> only answers (the per-sample path: no result to fill),
// Checker<true> also records the first problem in *p.
template <bool kExplain>
struct Checker {
    ValueProblem* p = nullptr;

    bool fail(const char* field, int index, double value, const char* problem = nullptr) {
        if constexpr (kExplain) *p = ValueProblem{field, index, value, problem};
        return false;
    }

    bool finite(const char* field, const double* v, int n) {
        bool ok = true;
        for (int i = 0; i < n; ++i) ok &= std::isfinite(v[i]);  // no branch per element on the common path
        if (ok) return true;
        for (int i = 0; i < n; ++i)
            if (!std::isfinite(v[i])) return fail(field, n > 1 ? i : -1, v[i]);
        return false;
    }

    bool finite(const char* field, double v) { return std::isfinite(v) || fail(field, -1, v); }

    // A 3x3 row-major covariance: finite, symmetric and positive
    // semi-definite, each within kCovarianceTolerance of the variances'
    // scale (rounding in a filter's update stays far inside it). PSD by
    // Sylvester's criterion for semi-definite matrices: every principal
    // minor >= 0 (the diagonal, the three 2x2, the determinant).
    bool covariance(const char* field, const double* c) {
        return finite(field, c, 9) && semi_definite(field, c);
    }

    // The same, for a covariance known to be finite.
    bool semi_definite(const char* field, const double* c) {
        const double d0 = c[0], d1 = c[4], d2 = c[8];
        if (!(d0 >= 0 && d1 >= 0 && d2 >= 0)) {
            for (int i = 0; i < 3; ++i)
                if (c[4 * i] < 0) return fail(field, 4 * i, c[4 * i], "(negative variance)");
        }
        double s0, s1, s2;  // the symmetric parts of [0][1], [0][2], [1][2]
        if (!(off_diagonal(field, 1, c[1], c[3], d0 * d1, s0) &&
              off_diagonal(field, 2, c[2], c[6], d0 * d2, s1) &&
              off_diagonal(field, 5, c[5], c[7], d1 * d2, s2)))
            return false;
        constexpr double tol = kCovarianceTolerance;
        const double det = d0 * d1 * d2 + 2 * s0 * s1 * s2 - d0 * s2 * s2 - d1 * s1 * s1 - d2 * s0 * s0;
        return det >= -tol * d0 * d1 * d2 || fail(field, -1, det, "as determinant (not positive semi-definite)");
    }

    // Element [i][j] = a (at index) and [j][i] = b of a covariance whose
    // variances multiply to vv: symmetric, and a correlation of at most 1.
    bool off_diagonal(const char* field, int index, double a, double b, double vv, double& s) {
        constexpr double tol = kCovarianceTolerance;
        if (a != b && (a - b) * (a - b) > tol * tol * vv)
            return fail(field, index, a, "(not symmetric with its transposed element)");
        s = 0.5 * (a + b);
        return s * s <= vv * (1 + tol) ||
               fail(field, index, s, "(a correlation above 1: not positive semi-definite)");
    }

    bool unit_quaternion(const char* field, const double* q) {
        return finite(field, q, 4) && unit_norm(field, q);
    }

    // The same, for a quaternion known to be finite.
    bool unit_norm(const char* field, const double* q) {
        // | |q| - 1 | <= tol, compared on the squared norm: no square root unless it fails.
        constexpr double lo = (1 - kUnitQuaternionTolerance) * (1 - kUnitQuaternionTolerance);
        constexpr double hi = (1 + kUnitQuaternionTolerance) * (1 + kUnitQuaternionTolerance);
        const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (n2 >= lo && n2 <= hi) return true;
        return fail(field, -1, std::sqrt(n2), "in norm, not a unit quaternion");
    }

    bool check(const pn_record_header_t* h) {
        switch (h->type) {
            case PN_REC_IMU: {
                auto* r = reinterpret_cast<const pn_imu_t*>(h);
                return finite("accel_mps2", r->accel_mps2, 3) && finite("gyro_radps", r->gyro_radps, 3);
            }
            case PN_REC_MAG: return finite("mag_ut", reinterpret_cast<const pn_mag_t*>(h)->mag_ut, 3);
            case PN_REC_BARO: {
                const double pa = reinterpret_cast<const pn_baro_t*>(h)->pressure_pa;
                return finite("pressure_pa", pa) && (pa > 0 || fail("pressure_pa", -1, pa, "(not positive)"));
            }
            case PN_REC_GNSS: {
                auto* r = reinterpret_cast<const pn_gnss_t*>(h);
                return finite("lat_deg", r->lat_deg) && finite("lon_deg", r->lon_deg) &&
                       (std::fabs(r->lat_deg) <= 90 || fail("lat_deg", -1, r->lat_deg, "(beyond 90 degrees)")) &&
                       (std::fabs(r->lon_deg) <= 180 || fail("lon_deg", -1, r->lon_deg, "(beyond 180 degrees)")) &&
                       finite("h_accuracy_m", r->h_accuracy_m);
            }
            case PN_REC_GAIT_PHASE:
                return finite("statistic", reinterpret_cast<const pn_gait_phase_t*>(h)->statistic);
            case PN_REC_STEP: {
                auto* r = reinterpret_cast<const pn_step_t*>(h);
                const bool has_extremes = r->header.struct_size >= offsetof(pn_step_t, accel_min_mps2) + sizeof(double);
                return finite("accel_peak_to_peak_mps2", r->accel_peak_to_peak_mps2) &&
                       finite("frequency_hz", r->frequency_hz) &&
                       (!has_extremes ||
                        (finite("accel_max_mps2", r->accel_max_mps2) && finite("accel_min_mps2", r->accel_min_mps2)));
            }
            case PN_REC_ATTITUDE: {
                auto* r = reinterpret_cast<const pn_attitude_t*>(h);
                return unit_quaternion("q_enu_from_body", r->q_enu_from_body) && finite("heading_rad", r->heading_rad) &&
                       finite("gyro_bias_radps", r->gyro_bias_radps, 3) &&
                       covariance("cov_attitude_rad2", r->cov_attitude_rad2);
            }
            case PN_REC_ATTITUDE_CORRECTION: {
                auto* r = reinterpret_cast<const pn_attitude_correction_t*>(h);
                return finite("rotation_enu_rad", r->rotation_enu_rad, 3) &&
                       finite("gyro_bias_delta_radps", r->gyro_bias_delta_radps, 3);
            }
            case PN_REC_POSITION: {
                auto* r = reinterpret_cast<const pn_position_t*>(h);
                return finite("pos_enu_m", r->pos_enu_m, 3) &&
                       (!(r->header.flags & PN_POSITION_FLAG_HAS_VELOCITY) || finite("vel_enu_mps", r->vel_enu_mps, 3)) &&
                       finite("heading_rad", r->heading_rad) && covariance("cov_enu_m2", r->cov_enu_m2);
            }
            case PN_REC_STRIDE: {
                auto* r = reinterpret_cast<const pn_stride_t*>(h);
                return finite("displacement_enu_m", r->displacement_enu_m, 3) && finite("length_m", r->length_m) &&
                       finite("heading_change_rad", r->heading_change_rad) &&
                       covariance("cov_displacement_m2", r->cov_displacement_m2);
            }
            default: return true;
        }
    }
};

// True when the n values are finite, told from their sum: a NaN or an
// infinity makes any sum NaN or infinite, so a finite sum proves every value
// finite with one addition per value (four chains, for the latency). A sum
// that overflows proves nothing; the caller then asks the exact check.
inline bool sum_finite(const double* v, int n) {
    double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        a0 += v[i];
        a1 += v[i + 1];
        a2 += v[i + 2];
        a3 += v[i + 3];
    }
    for (; i < n; ++i) a0 += v[i];
    const double sum = (a0 + a1) + (a2 + a3);
    return sum - sum == 0.0;
}

// The doubles of a record checked for finiteness, in runs of fields that lie
// one after the other (pinned here, the layout sentinels pin the ABI).
#define PEDNAV_FOLLOWS(T, a, na, b) \
    static_assert(offsetof(T, b) == offsetof(T, a) + (na) * sizeof(double), #b)
PEDNAV_FOLLOWS(pn_imu_t, accel_mps2, 3, gyro_radps);
PEDNAV_FOLLOWS(pn_attitude_t, q_enu_from_body, 4, heading_rad);
PEDNAV_FOLLOWS(pn_attitude_t, heading_rad, 1, gyro_bias_radps);
PEDNAV_FOLLOWS(pn_attitude_t, gyro_bias_radps, 3, cov_attitude_rad2);
PEDNAV_FOLLOWS(pn_attitude_correction_t, rotation_enu_rad, 3, gyro_bias_delta_radps);
PEDNAV_FOLLOWS(pn_position_t, pos_enu_m, 3, vel_enu_mps);
PEDNAV_FOLLOWS(pn_position_t, vel_enu_mps, 3, cov_enu_m2);
PEDNAV_FOLLOWS(pn_position_t, cov_enu_m2, 9, heading_rad);
PEDNAV_FOLLOWS(pn_stride_t, displacement_enu_m, 3, length_m);
PEDNAV_FOLLOWS(pn_stride_t, length_m, 1, heading_change_rad);
PEDNAV_FOLLOWS(pn_stride_t, heading_change_rad, 1, cov_displacement_m2);
PEDNAV_FOLLOWS(pn_step_t, accel_peak_to_peak_mps2, 1, frequency_hz);
#undef PEDNAV_FOLLOWS

bool exact(const pn_record_header_t* h) { return Checker<false>{}.check(h); }

// Per type: fine for sure from the sums and the same range checks as Checker,
// else the exact check's verdict.
bool imu_ok(const pn_record_header_t* h) {
    return sum_finite(reinterpret_cast<const pn_imu_t*>(h)->accel_mps2, 6) || exact(h);
}
bool mag_ok(const pn_record_header_t* h) {
    return sum_finite(reinterpret_cast<const pn_mag_t*>(h)->mag_ut, 3) || exact(h);
}
bool baro_ok(const pn_record_header_t* h) {
    const double pa = reinterpret_cast<const pn_baro_t*>(h)->pressure_pa;
    return (pa > 0 && pa <= std::numeric_limits<double>::max()) || exact(h);
}
bool gait_phase_ok(const pn_record_header_t* h) {
    return sum_finite(&reinterpret_cast<const pn_gait_phase_t*>(h)->statistic, 1) || exact(h);
}
// A covariance of zeros ("unknown", as pn_types.h allows) passes every
// check of Checker::semi_definite (+0 and -0 alike): told by one OR over its
// bits, without the sign.
bool all_zero(const double* c, int n) {
    uint64_t bits = 0;
    for (int i = 0; i < n; ++i) {
        uint64_t b;
        std::memcpy(&b, &c[i], sizeof b);
        bits |= b;
    }
    return (bits << 1) == 0;
}

bool attitude_ok(const pn_record_header_t* h) {
    auto* r = reinterpret_cast<const pn_attitude_t*>(h);
    Checker<false> c;
    return (sum_finite(r->q_enu_from_body, 17) && c.unit_norm("", r->q_enu_from_body) &&
            (all_zero(r->cov_attitude_rad2, 9) || c.semi_definite("", r->cov_attitude_rad2))) ||
           exact(h);
}
bool attitude_correction_ok(const pn_record_header_t* h) {
    return sum_finite(reinterpret_cast<const pn_attitude_correction_t*>(h)->rotation_enu_rad, 6) || exact(h);
}
bool position_ok(const pn_record_header_t* h) {
    auto* r = reinterpret_cast<const pn_position_t*>(h);
    const bool velocity = r->header.flags & PN_POSITION_FLAG_HAS_VELOCITY;
    return ((velocity ? sum_finite(r->pos_enu_m, 16)
                      : sum_finite(r->pos_enu_m, 3) && sum_finite(r->cov_enu_m2, 10)) &&
            Checker<false>{}.semi_definite("", r->cov_enu_m2)) ||
           exact(h);
}
bool stride_ok(const pn_record_header_t* h) {
    auto* r = reinterpret_cast<const pn_stride_t*>(h);
    return (sum_finite(r->displacement_enu_m, 14) &&
            Checker<false>{}.semi_definite("", r->cov_displacement_m2)) ||
           exact(h);
}

}  // namespace

ValuesCheck values_check_for(pn_record_type_t type) {
    switch (type) {
        case PN_REC_IMU: return &imu_ok;
        case PN_REC_MAG: return &mag_ok;
        case PN_REC_BARO: return &baro_ok;
        case PN_REC_GAIT_PHASE: return &gait_phase_ok;
        case PN_REC_ATTITUDE: return &attitude_ok;
        case PN_REC_ATTITUDE_CORRECTION: return &attitude_correction_ok;
        case PN_REC_POSITION: return &position_ok;
        case PN_REC_STRIDE: return &stride_ok;
        default: return &exact;  // the rarer types (GNSS, steps) and unknown ones
    }
}

bool record_values_ok(const pn_record_header_t* h) { return values_check_for(h->type)(h); }

ValueProblem find_value_problem(const pn_record_header_t* h) {
    ValueProblem p;
    Checker<true>{&p}.check(h);
    return p;
}

void format_value_problem(const ValueProblem& p, char* buffer, size_t capacity) {
    if (!capacity) return;
    buffer[0] = '\0';
    if (!p) return;
    char index[16] = "";
    if (p.index >= 0) std::snprintf(index, sizeof index, "[%d]", p.index);
    std::snprintf(buffer, capacity, "%s%s is %g%s%s", p.field, index, p.value, p.problem ? " " : "",
                  p.problem ? p.problem : "");
}

std::string describe(const ValueProblem& p) {
    char buf[160];
    format_value_problem(p, buf, sizeof buf);
    return buf;
}

}  // namespace pednav::engine
