// SPDX-License-Identifier: Apache-2.0
#include "pednav_validate/output_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <pednav/pn_engine.h>

namespace pednav::validate {

bool symmetric_psd(const double* c) {
    for (int i = 0; i < 9; ++i)
        if (!std::isfinite(c[i])) return false;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::fabs(c[3 * i + j] - c[3 * j + i]) > 1e-9 * (1 + std::fabs(c[3 * i + j]))) return false;
    const double m1 = c[0];
    const double m2 = c[0] * c[4] - c[1] * c[3];
    const double m3 = c[0] * (c[4] * c[8] - c[5] * c[7]) - c[1] * (c[3] * c[8] - c[5] * c[6]) +
                      c[2] * (c[3] * c[7] - c[4] * c[6]);
    const double scale = std::max({std::fabs(c[0]), std::fabs(c[4]), std::fabs(c[8]), 1e-30});
    // Leading minors alone miss a matrix with a zero first pivot: the diagonal must be non-negative too.
    return m1 >= -1e-12 * scale && c[4] >= -1e-12 * scale && c[8] >= -1e-12 * scale &&
           m2 >= -1e-9 * scale * scale && m3 >= -1e-9 * scale * scale * scale;
}

namespace {

const char* type_name(uint32_t type) {
    switch (type) {
        case PN_REC_POSITION: return "position";
        case PN_REC_STRIDE: return "stride";
        case PN_REC_STEP: return "step";
        case PN_REC_ATTITUDE: return "attitude";
        case PN_REC_GAIT_PHASE: return "gait_phase";
        default: return "other";
    }
}

bool all_finite(const double* v, int n) {
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}

}  // namespace

OutputSummary check_outputs(const std::vector<OutputBytes>& outputs) {
    OutputSummary s;
    int64_t last_t[PN_REC_TYPE_COUNT];
    for (auto& t : last_t) t = INT64_MIN;
    constexpr size_t kMaxProblems = 8;
    for (size_t k = 0; k < outputs.size(); ++k) {
        pn_output_t o;
        std::memset(&o, 0, sizeof o);
        std::memcpy(&o, outputs[k].data(), std::min(outputs[k].size(), sizeof o));
        const uint32_t type = o.header.type;
        ++s.count;
        auto problem = [&](const std::string& what) {
            if (s.problems.size() < kMaxProblems)
                s.problems.push_back("output " + std::to_string(k) + " (" + type_name(type) + ", t " +
                                     std::to_string(o.header.t_ns) + " ns, stage " +
                                     std::to_string(o.header.source_id) + "): " + what);
        };
        if (type >= PN_REC_TYPE_COUNT) {
            problem("unknown record type " + std::to_string(type));
            continue;
        }
        if (o.header.t_ns < last_t[type]) problem("earlier than the output before it of the same type");
        last_t[type] = std::max(last_t[type], o.header.t_ns);
        if (type == PN_REC_POSITION) {
            ++s.positions;
            if (!all_finite(o.position.pos_enu_m, 3)) problem("pos_enu_m not finite");
            if (!symmetric_psd(o.position.cov_enu_m2)) problem("cov_enu_m2 not symmetric positive semi-definite");
        } else if (type == PN_REC_ATTITUDE) {
            ++s.attitudes;
            const double* q = o.attitude.q_enu_from_body;
            if (!all_finite(q, 4) || std::fabs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1) > 1e-6)
                problem("q_enu_from_body not a unit quaternion");
            if (!symmetric_psd(o.attitude.cov_attitude_rad2))
                problem("cov_attitude_rad2 not symmetric positive semi-definite");
        } else if (type == PN_REC_STRIDE) {
            ++s.strides;
            if (!symmetric_psd(o.stride.cov_displacement_m2))
                problem("cov_displacement_m2 not symmetric positive semi-definite");
            if (!(o.stride.length_m >= 0)) problem("length_m negative or not finite");
        } else if (type == PN_REC_STEP) {
            ++s.steps;
        } else if (type == PN_REC_GAIT_PHASE) {
            ++s.gait_phases;
        }
    }
    return s;
}

}  // namespace pednav::validate
