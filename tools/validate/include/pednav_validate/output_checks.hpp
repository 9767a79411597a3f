// SPDX-License-Identifier: Apache-2.0
// What every output of a pipeline must satisfy, whichever plugin made it:
// time-ordered per record type, finite, unit quaternions, symmetric positive
// semi-definite covariances, non-negative stride lengths.
#pragma once

#include <string>
#include <vector>

namespace pednav::validate {

// One polled output, its bytes as the engine gave them (pn_output_t, struct_size bytes).
using OutputBytes = std::string;

// True when the row-major 3x3 matrix is symmetric and positive semi-definite
// (Sylvester's criterion on the leading minors, with round-off tolerance).
bool symmetric_psd(const double* c_row_major_3x3);

struct OutputSummary {
    size_t count = 0;
    size_t positions = 0, strides = 0, steps = 0, attitudes = 0, gait_phases = 0;
    std::vector<std::string> problems;  // "output 12 (position, stage 3): cov_enu_m2 not positive semi-definite"
};

OutputSummary check_outputs(const std::vector<OutputBytes>& outputs);

}  // namespace pednav::validate
