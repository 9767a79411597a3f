// SPDX-License-Identifier: Apache-2.0
#include "gnss_fix.hpp"

#include <cstdio>

#include "pednav_io/gnss_log.hpp"

namespace pednav::io::detail {

namespace {

constexpr double kDegToRad = 0.017453292519943295;

bool given(double v) { return std::isfinite(v); }

std::string text(const char* format, double v) {
    char buffer[120];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

}  // namespace

pn_gnss_t make_gnss_fix(const FixFields& f, double uere_m, std::string* problem, AccuracySource* source) {
    pn_gnss_t g{};
    g.header.struct_size = sizeof g;
    g.header.type = PN_REC_GNSS;
    problem->clear();
    if (!given(f.lat_deg) || std::fabs(f.lat_deg) > 90.0) {
        *problem = given(f.lat_deg) ? text("latitude %.9g beyond 90 degrees", f.lat_deg) : "no latitude";
        return g;
    }
    if (!given(f.lon_deg) || std::fabs(f.lon_deg) > 180.0) {
        *problem = given(f.lon_deg) ? text("longitude %.9g beyond 180 degrees", f.lon_deg) : "no longitude";
        return g;
    }
    if (given(f.h_sigma_m) && !(f.h_sigma_m > 0.0)) {
        *problem = text("horizontal accuracy %.9g m is not positive", f.h_sigma_m);
        return g;
    }
    if (given(f.v_sigma_m) && !(f.v_sigma_m > 0.0)) {
        *problem = text("vertical accuracy %.9g m is not positive", f.v_sigma_m);
        return g;
    }
    if (given(f.speed_mps) && f.speed_mps < 0.0) {
        *problem = text("negative speed %.9g m/s", f.speed_mps);
        return g;
    }
    g.lat_deg = f.lat_deg;
    g.lon_deg = f.lon_deg;
    g.satellites = f.satellites;
    g.fix_type = f.fix_type;
    g.utc_ns = f.utc_ns;

    // Horizontal: the file's sigma, else HDOP x UERE, else UERE (HDOP 1 assumed).
    *source = AccuracySource::sigma;
    if (given(f.h_sigma_m)) {
        g.h_accuracy_m = f.h_sigma_m;
    } else if (given(f.hdop) && f.hdop > 0.0) {
        g.h_accuracy_m = f.hdop * uere_m;
        *source = AccuracySource::dop;
    } else {
        g.h_accuracy_m = uere_m;
        *source = AccuracySource::assumed;
    }
    // Vertical: the file's sigma, else VDOP x UERE, else 1.5 x horizontal;
    // a fix without a (reliable) height gets no vertical weight.
    if (!given(f.height_m) || !f.height_reliable) {
        g.height_m = given(f.height_m) ? f.height_m : 0.0;
        g.v_accuracy_m = kGnssNoHeightAccuracy_m;
    } else {
        g.height_m = f.height_m;
        if (given(f.v_sigma_m))
            g.v_accuracy_m = f.v_sigma_m;
        else if (given(f.vdop) && f.vdop > 0.0)
            g.v_accuracy_m = f.vdop * uere_m;
        else
            g.v_accuracy_m = 1.5 * g.h_accuracy_m;
    }
    // Velocity: speed and course; a receiver standing still often leaves the
    // course empty, and zero speed needs none.
    if (given(f.speed_mps) && (given(f.course_deg) || f.speed_mps == 0.0)) {
        const double c = given(f.course_deg) ? f.course_deg * kDegToRad : 0.0;
        g.vel_enu_mps[0] = f.speed_mps * std::sin(c);
        g.vel_enu_mps[1] = f.speed_mps * std::cos(c);
        g.vel_enu_mps[2] = 0.0;
        g.header.flags |= PN_GNSS_FLAG_HAS_VELOCITY;
    }
    return g;
}

std::string accuracy_note(const size_t counts[3], double uere_m) {
    char buffer[240];
    std::snprintf(buffer, sizeof buffer,
                  "horizontal accuracy: %zu fixes from the file's sigmas, %zu from HDOP x UERE (%.3g m), %zu "
                  "without either (UERE taken, HDOP 1 assumed)",
                  counts[0], counts[1], uere_m, counts[2]);
    return buffer;
}

}  // namespace pednav::io::detail
