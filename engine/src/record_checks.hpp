// SPDX-License-Identifier: Apache-2.0
// Contract checks on records crossing the engine: app inputs before they enter
// the pipeline, plugin outputs before the sink accepts them.
#pragma once

#include <string>

#include <pednav/pn_types.h>

namespace pednav::engine {

// Smallest struct_size accepted for a record type (the 1.0 size), 0 if unknown.
inline uint32_t min_record_size(pn_record_type_t type) {
    // Indexed by type; there is no type 0.
    static constexpr uint32_t kMinSize[PN_REC_TYPE_COUNT] = {
        0, PN_IMU_MIN_SIZE, PN_MAG_MIN_SIZE, PN_BARO_MIN_SIZE, PN_GNSS_MIN_SIZE, PN_GAIT_PHASE_MIN_SIZE,
        PN_STEP_MIN_SIZE, PN_ATTITUDE_MIN_SIZE, PN_ATTITUDE_CORRECTION_MIN_SIZE, PN_POSITION_MIN_SIZE,
        PN_STRIDE_MIN_SIZE};
    static_assert(PN_REC_STRIDE == 10 && PN_REC_TYPE_COUNT == 11, "one size per type");
    return type < PN_REC_TYPE_COUNT ? kMinSize[type] : 0;
}
const char* record_type_name(pn_record_type_t type);  // "imu", "position", ... or "unknown"

constexpr uint64_t kInputTypes = PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_MAG) |
                                 PN_REC_MASK(PN_REC_BARO) | PN_REC_MASK(PN_REC_GNSS);

// A covariance is symmetric when |c_ij - c_ji| <= this * sqrt(c_ii c_jj), and
// positive semi-definite when its principal minors are >= -this times the
// product of their variances.
constexpr double kCovarianceTolerance = 1e-6;

// A quaternion is of unit norm when | |q| - 1 | <= this.
constexpr double kUnitQuaternionTolerance = 1e-3;

// The first value of a record a consumer could not rely on: not finite, or out
// of physical range (covariances symmetric positive semi-definite, quaternions of unit
// norm, pressure positive, latitude and longitude in range). Nothing in it is
// allocated; the text is made by describe() or format_value_problem() only
// for a refused record.
struct ValueProblem {
    const char* field = nullptr;    // nullptr: every value is fine
    int index = -1;                 // element of an array field, -1 for a scalar
    double value = 0;               // the offending value (the norm, for a quaternion)
    const char* problem = nullptr;  // what is wrong when it is finite, e.g. "(negative variance)"

    explicit operator bool() const { return field != nullptr; }
};

ValueProblem find_value_problem(const pn_record_header_t* record);
// The same verdict, !find_value_problem(record), from the same checks with
// nothing to fill in: the per-sample path. For the per-sample types it first
// proves the values finite from their sums (one addition per value), and runs
// the element-by-element checks only when a sum is not finite.
bool record_values_ok(const pn_record_header_t* record);
// record_values_ok for one type, without the dispatch on the type: the sink
// looks it up once per stage and type.
using ValuesCheck = bool (*)(const pn_record_header_t* record);
ValuesCheck values_check_for(pn_record_type_t type);
// "accel_mps2[2] is nan", "cov_enu_m2[4] is -1 (negative variance)"; empty when fine.
std::string describe(const ValueProblem& problem);
// The same text into a caller's buffer, without allocating (the sink's path).
void format_value_problem(const ValueProblem& problem, char* buffer, size_t capacity);

}  // namespace pednav::engine
