// Contract checks on records crossing the engine: app inputs before they enter
// the pipeline, plugin outputs before the sink accepts them.
#pragma once

#include <string>

#include <pednav/pn_types.h>

namespace pednav::engine {

// Smallest struct_size accepted for a record type (the 1.0 size), 0 if unknown.
uint32_t min_record_size(pn_record_type_t type);
const char* record_type_name(pn_record_type_t type);  // "imu", "position", ... or "unknown"

constexpr uint64_t kInputTypes = PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_MAG) |
                                 PN_REC_MASK(PN_REC_BARO) | PN_REC_MASK(PN_REC_GNSS);

// Empty when fine, else the problem ("accel_mps2[2] is NaN"). Checks that the
// values a consumer relies on are finite and in physical range (covariance
// diagonals non-negative, quaternions of unit norm).
std::string check_record_values(const pn_record_header_t* record);
// The same verdict without building a message: the per-sample path.
bool record_values_ok(const pn_record_header_t* record);

}  // namespace pednav::engine
