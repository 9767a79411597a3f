// SPDX-License-Identifier: Apache-2.0
// Height changes and floors from a barometer.
//
// Altitude is the barometric formula of the standard atmosphere
// (pednav::geodesy::pressure_altitude_m) above a reference pressure, with the
// standard temperature of the reference's own altitude, not a fixed
// metres-per-pascal factor: -0.083 m/Pa holds near sea level only
// (ERRATA.md, chest paper eq. 5), and is 10 % off 900 m higher.
//
// The reference pressure is learnt: the mean over the first reference_s of
// readings, taken as altitude 0 on floor 0 (the start). Weather moves the
// pressure by about 1 hPa in 3 h (8 m), so a long walk drifts; a place of
// known height (a map's altitude-update zone) re-anchors it with
// set_altitude(). Floors are altitude / floor_height_m rounded, with a
// hysteresis so that noise at a floor's half-height does not flip it.
#pragma once

#include <cstdint>
#include <string>

namespace pednav::barometry {

struct BarometricAltimeterConfig {
    double reference_s;         // learn the reference pressure over this long, s (> 0)
    double smoothing_s;         // time constant of the altitude low-pass, s (>= 0; 0 = none)
    double rate_smoothing_s;    // time constant of the vertical rate's low-pass, s (> 0)
    double floor_height_m;      // height of one floor, m (> 0)
    double floor_hysteresis_m;  // beyond half a floor by this much before the floor changes, m (>= 0)
    double max_gap_s;           // a gap longer than this restarts the filters from the next reading, s (> 0)
};

// Fills a config from a params view (any type with number(key)) under the
// keys of the struct's fields, prefixed with `prefix` (e.g. "baro_").
template <class Params>
BarometricAltimeterConfig barometric_altimeter_config(Params& v, const char* prefix = "baro_") {
    const auto key = [prefix](const char* name) { return std::string(prefix) + name; };
    BarometricAltimeterConfig c;
    c.reference_s = v.number(key("reference_s"));
    c.smoothing_s = v.number(key("smoothing_s"));
    c.rate_smoothing_s = v.number(key("rate_smoothing_s"));
    c.floor_height_m = v.number(key("floor_height_m"));
    c.floor_hysteresis_m = v.number(key("floor_hysteresis_m"));
    c.max_gap_s = v.number(key("max_gap_s"));
    return c;
}

class BarometricAltimeter {
public:
    // Throws std::invalid_argument for a config out of range.
    explicit BarometricAltimeter(const BarometricAltimeterConfig& config);

    // One reading (t_ns increasing, pressure_pa > 0; others are ignored and
    // counted in rejected()).
    void push(int64_t t_ns, double pressure_pa);

    // The reference pressure is known (reference_s of readings seen).
    bool ready() const { return ready_; }
    // Filtered altitude above the start (m), 0 until ready.
    double altitude_m() const { return ready_ ? altitude_m_ + offset_m_ : 0.0; }
    // Filtered vertical rate, m/s, 0 until ready.
    double vertical_rate_mps() const { return rate_mps_; }
    // Floor index from altitude and floor height (0 = the start floor).
    int floor() const { return floor_; }
    double reference_pa() const { return reference_pa_; }
    int64_t rejected() const { return rejected_; }

    // The walker is at a place of known altitude (m above the start level) and
    // on a known floor: shift the altitude to it from now on. Ignored until ready.
    void set_altitude(double altitude_m, int floor);
    // A floor change known from elsewhere (a lift or stairs the map says were
    // taken), without a known altitude.
    void set_floor(int floor) { floor_ = floor; }

    void reset();

private:
    void update_floor();

    BarometricAltimeterConfig c_;
    bool ready_ = false;
    bool has_last_ = false;
    int64_t t_first_ns_ = 0, t_last_ns_ = 0;
    double sum_pa_ = 0;
    int64_t n_ = 0;
    double reference_pa_ = 0;
    double reference_altitude_m_ = 0;  // standard-atmosphere altitude of reference_pa_
    double altitude_m_ = 0;  // filtered, from the reference
    double offset_m_ = 0;    // set_altitude's shift
    double rate_mps_ = 0;
    int floor_ = 0;
    int64_t rejected_ = 0;
};

}  // namespace pednav::barometry
