// SPDX-License-Identifier: Apache-2.0
// Initial alignment and bias-compensated attitude integration of a strapdown
// IMU (sensor axes, any orientation on the body; the foot attitude estimator
// runs it on the shoe).
//
// Alignment: the first still period of at least align_still_s (or, when the
// motion starts earlier, of at least align_min_still_s) gives roll and pitch
// from the mean specific force, the initial gyro bias from the mean rate, and
// the heading from the tilt-compensated magnetometer (when present and its
// field strength is plausible) plus the declination, else initial_heading_deg.
//
// Attitude update: q_k = q_{k-1} (x) exp(theta_k) with the rotation vector of
// the interval from the mid-interval (trapezoidal) bias-compensated rate plus
// the coning term of a linearly varying rate:
//   theta = (w_{k-1} + w_k)/2 dt + (w_{k-1} x w_k) dt^2 / 12.
// This replaces the end-of-interval Cayley step of foot-imu-zupt-zaru-ekf
// eq. (8); both agree to first order.
#pragma once

#include <cstdint>

#include "alignment.hpp"
#include "so3.hpp"

namespace pednav::navmath {

// No defaults here: the strapdown plugin's parameter schema holds them, with
// their ranges (pednav plugins --params); strapdown_config() fills every field.
struct StrapdownConfig {
    double align_still_s;           // still time that triggers the alignment
    double align_min_still_s;       // shortest still period accepted when motion starts
    double align_timeout_s;        // align on the current sample after this long without a still period
    double align_gyro_max_radps;   // still: |w| below this
    double align_accel_dev_mps2;    // still: |a - mean a| below this
    bool use_magnetometer;
    double mag_min_ut;             // field strengths outside [min, max] are not trusted
    double mag_max_ut;
    double declination_deg;         // east positive: true = magnetic + declination
    double initial_heading_deg;     // when no trusted magnetometer; clockwise from north
    bool gyro_bias_from_still;     // initial gyro bias = mean rate of the still period...
    double bias_still_max_sd_radps;  // ...when the rate's sd over it is below this (truly still)
    bool coning;                   // second-order coning term
    double max_dt_s;                // longer gaps are integrated as this
    // Gyro full-scale range; samples at or above 99.5 % of it are clipped and
    // the missing rotation of each clipped run is restored at its end from a
    // parabola through the run with the entry and exit slopes. 0 = off.
    double gyro_range_radps;
};

// The config from named values: `v.number(key)` and `v.boolean(key)` for each
// field, by its name (a plugin's SDK Params, whose schema gives defaults and
// ranges; a test's values read from that schema).
template <class Values>
StrapdownConfig strapdown_config(Values& v) {
    StrapdownConfig c;
    c.align_still_s = v.number("align_still_s");
    c.align_min_still_s = v.number("align_min_still_s");
    c.align_timeout_s = v.number("align_timeout_s");
    c.align_gyro_max_radps = v.number("align_gyro_max_radps");
    c.align_accel_dev_mps2 = v.number("align_accel_dev_mps2");
    c.use_magnetometer = v.boolean("use_magnetometer");
    c.mag_min_ut = v.number("mag_min_ut");
    c.mag_max_ut = v.number("mag_max_ut");
    c.declination_deg = v.number("declination_deg");
    c.initial_heading_deg = v.number("initial_heading_deg");
    c.gyro_bias_from_still = v.boolean("gyro_bias_from_still");
    c.bias_still_max_sd_radps = v.number("bias_still_max_sd_radps");
    c.coning = v.boolean("coning");
    c.max_dt_s = v.number("max_dt_s");
    c.gyro_range_radps = v.number("gyro_range_radps");
    return c;
}

class Strapdown {
public:
    explicit Strapdown(const StrapdownConfig& c) : cfg_(c) {}

    // Feeds one IMU sample. Returns true when an attitude is available for it.
    bool on_imu(int64_t t_ns, const Vec3& accel_mps2, const Vec3& gyro_radps);
    void on_mag(int64_t t_ns, const Vec3& mag_ut);
    // q_new = exp(rotation_enu_rad) q_old; bias += gyro_bias_delta_radps.
    void apply_correction(const Vec3& rotation_enu_rad, const Vec3& gyro_bias_delta_radps);
    // Overrides the attitude (and marks the estimator aligned).
    void set_attitude(const Quat& q_enu_from_body);

    const Quat& q() const { return q_; }
    const Vec3& gyro_bias() const { return bias_; }
    bool heading_from_magnetometer() const { return heading_from_mag_; }

private:
    void align();
    void reset_still();

    StrapdownConfig cfg_;
    bool aligned_ = false;
    bool heading_from_mag_ = false;
    Quat q_ = Quat::Identity();
    Vec3 bias_ = Vec3::Zero();
    Vec3 w_prev_ = Vec3::Zero();  // raw rate of the previous sample
    int64_t t_prev_ = 0;
    bool have_prev_ = false;

    // Still-period accumulators.
    int64_t t_first_ = 0;
    int64_t t_still_start_ = 0;
    int64_t t_still_last_ = 0;
    bool first_seen_ = false;
    Vec3 sum_a_ = Vec3::Zero();
    Vec3 sum_w_ = Vec3::Zero();
    Vec3 sum_w2_ = Vec3::Zero();
    double n_still_ = 0;
    Vec3 sum_m_ = Vec3::Zero();
    double n_mag_ = 0;
    Vec3 last_a_ = Vec3::Zero();

    // Clipping repair, per axis.
    void repair_clipping(const Vec3& w, double dt);
    Vec3 w_prev2_ = Vec3::Zero();
    int clip_len_[3] = {0, 0, 0};
    double clip_entry_slope_[3] = {0, 0, 0};
    double clip_time_[3] = {0, 0, 0};
};

}  // namespace pednav::navmath
