// SPDX-License-Identifier: Apache-2.0
#include "pednav_barometry/barometric_altimeter.hpp"

#include <cmath>
#include <stdexcept>

#include <pednav_geodesy/atmosphere.hpp>

namespace pednav::barometry {

namespace {

// Height of pressure p above the level of p_ref: the difference of their
// standard-atmosphere altitudes. That uses the standard temperature at the
// reference's own altitude (9 C at 900 m) where pressure_altitude_m(p, p_ref)
// would take 15 C and read 2 % high at 900 m.
double height_above_m(double p, double reference_altitude_m) {
    return geodesy::pressure_altitude_m(p) - reference_altitude_m;
}

}  // namespace

BarometricAltimeter::BarometricAltimeter(const BarometricAltimeterConfig& c) : c_(c) {
    if (!(c.reference_s > 0)) throw std::invalid_argument("reference_s must be positive");
    if (!(c.smoothing_s >= 0)) throw std::invalid_argument("smoothing_s must not be negative");
    if (!(c.rate_smoothing_s > 0)) throw std::invalid_argument("rate_smoothing_s must be positive");
    if (!(c.floor_height_m > 0)) throw std::invalid_argument("floor_height_m must be positive");
    if (!(c.floor_hysteresis_m >= 0) || !(c.floor_hysteresis_m < 0.5 * c.floor_height_m))
        throw std::invalid_argument("floor_hysteresis_m must be in [0, floor_height_m / 2)");
    if (!(c.max_gap_s > 0)) throw std::invalid_argument("max_gap_s must be positive");
}

void BarometricAltimeter::reset() {
    const BarometricAltimeterConfig c = c_;
    *this = BarometricAltimeter(c);
}

void BarometricAltimeter::push(int64_t t_ns, double p) {
    if (!(p > 0) || !std::isfinite(p) || (has_last_ && t_ns <= t_last_ns_)) {
        ++rejected_;
        return;
    }
    const double dt = has_last_ ? 1e-9 * static_cast<double>(t_ns - t_last_ns_) : 0.0;
    if (!has_last_) t_first_ns_ = t_ns;
    has_last_ = true;
    t_last_ns_ = t_ns;
    if (!ready_) {
        sum_pa_ += p;
        ++n_;
        if (1e-9 * static_cast<double>(t_ns - t_first_ns_) >= c_.reference_s) {
            reference_pa_ = sum_pa_ / static_cast<double>(n_);
            ready_ = true;
            reference_altitude_m_ = geodesy::pressure_altitude_m(reference_pa_);
            altitude_m_ = height_above_m(p, reference_altitude_m_);
        }
        return;
    }
    const double h = height_above_m(p, reference_altitude_m_);
    if (dt > c_.max_gap_s) {  // the filters' memory is stale: start again at this reading
        altitude_m_ = h;
        rate_mps_ = 0;
        update_floor();
        return;
    }
    const double a = c_.smoothing_s > 0 ? 1.0 - std::exp(-dt / c_.smoothing_s) : 1.0;
    const double before = altitude_m_;
    altitude_m_ += a * (h - altitude_m_);
    const double ar = 1.0 - std::exp(-dt / c_.rate_smoothing_s);
    rate_mps_ += ar * ((altitude_m_ - before) / dt - rate_mps_);
    update_floor();
}

void BarometricAltimeter::update_floor() {
    const double level = altitude_m() / c_.floor_height_m;  // in floors
    const double margin = 0.5 + c_.floor_hysteresis_m / c_.floor_height_m;
    while (level > floor_ + margin) ++floor_;
    while (level < floor_ - margin) --floor_;
}

void BarometricAltimeter::set_altitude(double altitude_m, int floor) {
    if (!ready_) return;
    offset_m_ = altitude_m - altitude_m_;
    floor_ = floor;
}

}  // namespace pednav::barometry
