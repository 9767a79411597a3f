// SPDX-License-Identifier: Apache-2.0
// Internal: what the writers of run outputs share: the output file
// (out_file.hpp) and the fields of positions and strides as written.
#pragma once

#include <algorithm>
#include <cmath>

#include <pednav/pn_types.h>

#include "out_file.hpp"

namespace pednav::io::detail {

constexpr double kRadToDeg = 57.29577951308232;

inline double heading_deg(double heading_rad) {
    double d = std::fmod(heading_rad * kRadToDeg, 360.0);
    if (d < 0) d += 360.0;
    return d;
}

inline const char* class_name(int32_t c) {
    switch (c) {
        case PN_STRIDE_CLASS_LEVEL: return "level";
        case PN_STRIDE_CLASS_STAIRS_UP: return "stairs_up";
        case PN_STRIDE_CLASS_STAIRS_DOWN: return "stairs_down";
        default: return "unknown";
    }
}

inline bool has_floor(const pn_position_t& p) { return (p.header.flags & PN_POSITION_FLAG_HAS_FLOOR) != 0; }

inline double h_sigma_m(const pn_position_t& p) {
    return std::sqrt(std::max(0.0, p.cov_enu_m2[0] + p.cov_enu_m2[4]));
}

}  // namespace pednav::io::detail
