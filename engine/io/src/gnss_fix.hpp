// SPDX-License-Identifier: Apache-2.0
// Internal: one rule for turning what a GNSS file says about a fix into a
// pn_gnss_t, shared by the NMEA and CSV readers (docs/formats.md, "GNSS
// input"): accuracies from sigmas, else DOP x UERE; velocity from speed and
// course; the no-height convention.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <pednav/pn_types.h>

namespace pednav::io::detail {

// Fields of one fix as the file gives them; NaN = not given.
struct FixFields {
    double lat_deg = NAN;
    double lon_deg = NAN;
    double height_m = NAN;        // ellipsoidal
    double h_sigma_m = NAN;       // 1-sigma horizontal (radial rms, sqrt(sigma_e^2 + sigma_n^2))
    double v_sigma_m = NAN;       // 1-sigma vertical
    double hdop = NAN;
    double vdop = NAN;
    double speed_mps = NAN;       // horizontal speed over ground
    double course_deg = NAN;      // clockwise from true north
    int32_t satellites = 0;       // used in the fix, 0 = unknown
    int32_t fix_type = PN_GNSS_FIX_UNKNOWN;
    bool height_reliable = true;  // false for a 2D fix: the height is the receiver's held value
    int64_t utc_ns = 0;           // 0 = unknown
};

// How the accuracies of a fix were found (counted in the readers' notes).
enum class AccuracySource { sigma, dop, assumed };

// The record for `f` (t_ns left 0: the reader's LogBuilder sets it). When the
// fix cannot be a record, `problem` names why (latitude beyond 90 degrees,
// ...); otherwise it is left empty. uere_m is the 1-sigma range error that
// scales a DOP into metres.
pn_gnss_t make_gnss_fix(const FixFields& f, double uere_m, std::string* problem, AccuracySource* source);

// "horizontal accuracy: 3 fixes from the file's sigmas, 2 from HDOP x UERE
// (5 m), ..." for the reader's notes; counts indexed by AccuracySource.
std::string accuracy_note(const size_t counts[3], double uere_m);

}  // namespace pednav::io::detail
