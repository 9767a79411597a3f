// SPDX-License-Identifier: Apache-2.0
// Whether a magnetometer reading is the Earth's field and may correct a
// heading: its strength and its dip (inclination: the angle below the level
// plane, positive where the field points down, i.e. north of the magnetic
// equator) agree with the local field. Steel, motors and wiring change the
// strength or the dip, or both; a heading from such a reading is wrong.
//
// The local field is configured (strength in uT, dip in degrees) or learnt:
// the median strength and dip over the first learn_s of readings, medians so
// that a disturbance during part of that window does not set the reference.
// While learning, readings with a strength in [20, 70] uT (the Earth's range)
// are accepted.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "so3.hpp"

namespace pednav::navmath {

struct MagneticFieldGateConfig {
    double field_ut;            // local field strength, uT; 0 = learn it
    double dip_deg;             // local dip, deg, down positive; NaN = learn it
    double field_tolerance_ut;  // accepted |strength - local|, uT (> 0)
    double dip_tolerance_deg;   // accepted |dip - local|, deg (> 0)
    double learn_s;             // learning window, s (> 0)
};

// Fills a config from a params view (any type with number(key)); the keys are
// prefix + field name ("mag_field_ut", ...). A dip given as a number below
// -90 means "learn it" (JSON has no NaN).
template <class Params>
MagneticFieldGateConfig magnetic_field_gate_config(Params& v, const char* prefix = "mag_") {
    const auto key = [prefix](const char* name) { return std::string(prefix) + name; };
    MagneticFieldGateConfig c;
    c.field_ut = v.number(key("field_ut"));
    c.dip_deg = v.number(key("dip_deg"));
    if (c.dip_deg < -90.0) c.dip_deg = std::nan("");
    c.field_tolerance_ut = v.number(key("field_tolerance_ut"));
    c.dip_tolerance_deg = v.number(key("dip_tolerance_deg"));
    c.learn_s = v.number(key("learn_s"));
    return c;
}

class MagneticFieldGate {
public:
    // Throws std::invalid_argument for a config out of range.
    explicit MagneticFieldGate(const MagneticFieldGateConfig& config);

    // Judges one reading. mag_body_ut: the field in the body frame; up_body:
    // the unit up direction in the body frame (the third row of
    // R_enu_from_body, or the normalised specific force at rest).
    bool accept(int64_t t_ns, const Vec3& mag_body_ut, const Vec3& up_body);

    // The local field in use: configured, learnt, or NaN while learning.
    double field_ut() const { return field_ut_; }
    double dip_deg() const { return dip_deg_; }
    bool learnt() const { return std::isfinite(field_ut_) && std::isfinite(dip_deg_); }
    // The last reading's strength and dip.
    double last_field_ut() const { return last_field_ut_; }
    double last_dip_deg() const;

    void reset();

    // The dip of a field, deg, down positive.
    static double dip_of_deg(const Vec3& mag_body_ut, const Vec3& up_body);

private:
    void finish_learning();
    void set_dip_bounds();

    MagneticFieldGateConfig c_;
    double field_ut_, dip_deg_;
    double last_field_ut_ = 0, last_sin_dip_ = 0;
    double sin_dip_min_ = -1, sin_dip_max_ = 1;  // the accepted dips' sines
    bool learning_ = false;
    bool started_ = false;
    int64_t t_first_ns_ = 0;
    std::vector<double> learn_field_, learn_dip_;  // capacity reserved at construction
};

}  // namespace pednav::navmath
