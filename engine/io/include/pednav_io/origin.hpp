// SPDX-License-Identifier: Apache-2.0
// The origin of a recording's local ENU frame: a WGS-84 point (conversions in
// pednav_geodesy/enu.hpp), whether it is known, and the UTC of t_ns = 0, for
// ground-truth points read from files (IPIN POSI) and for the GeoJSON/GPX
// writers.
#pragma once

#include <cstdint>

#include <pednav_geodesy/enu.hpp>

namespace pednav::io {

struct Origin : geodesy::GeodeticPoint {
    bool known = false;
    int64_t utc_ns_at_zero = 0;  // UTC (ns since 1970) of t_ns = 0 when known, else 0; GPX writes <time> then
};

}  // namespace pednav::io
