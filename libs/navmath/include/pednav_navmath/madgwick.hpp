// SPDX-License-Identifier: Apache-2.0
// Madgwick's gradient-descent attitude filter (S. O. H. Madgwick, "An
// efficient orientation filter for inertial and inertial/magnetic sensor
// arrays", 2010; Madgwick, Harrison, Vaidyanathan, ICORR 2011), in its IMU
// form (gyro + accelerometer) and its MARG form (+ magnetometer), written for
// the engine's frames: q = q_enu_from_body, Hamilton, w first, ENU.
//
// Per sample (numbers are the 2010 report's equations):
//   q_dot_omega = 1/2 q (x) (0, omega - b)                            (eq. 12)
//   f(q) = [R(q)^T g_ref - a_hat ; R(q)^T b_ref - m_hat]              (eq. 19, 25, 31)
//     g_ref = (0, 0, 1): the accelerometer reads +g up at rest in ENU;
//     b_ref = (b_h sin D, b_h cos D, b_u): the measured field rotated into
//       ENU, h = R(q) m_hat, with b_h = |(h_e, h_n)|, b_u = h_u, turned to
//       magnetic north D east of true north (eq. 45-46, there with north on x);
//   grad = J(q)^T f(q)                                                 (eq. 20, 34)
//   q_dot = q_dot_omega - beta grad / |grad|                           (eq. 42-43)
//   q += q_dot dt, normalised.
// Gyro bias (eq. 47-48): omega_eps = 2 q* (x) (grad / |grad|), b += zeta omega_eps dt.
// With f written for ENU, the Jacobian of R^T d is that of the report with
// q1..q4 = w, x, y, z for d = (0, 0, 1); the x and y columns of d are derived
// the same way (madgwick.cpp).
#pragma once

#include <cstdint>

#include "so3.hpp"

namespace pednav::navmath {

struct MadgwickConfig {
    double gain_radps;            // beta, rad/s (>= 0)
    double gyro_bias_gain_radps;  // zeta, rad/s (>= 0; 0 = no bias estimate)
    double init_gain_radps;       // beta for the first init_s (fast convergence from the start), rad/s
    double init_s;                // s (>= 0)
    double declination_deg;       // magnetic north east of true north, deg
    double max_dt_s;              // longer gaps between samples are integrated as this, s (> 0)
};

template <class Params>
MadgwickConfig madgwick_config(Params& p) {
    MadgwickConfig c;
    c.gain_radps = p.number("gain_radps");
    c.gyro_bias_gain_radps = p.number("gyro_bias_gain_radps");
    c.init_gain_radps = p.number("init_gain_radps");
    c.init_s = p.number("init_s");
    c.declination_deg = p.number("declination_deg");
    c.max_dt_s = p.number("max_dt_s");
    return c;
}

class Madgwick {
public:
    // Throws std::invalid_argument for a config out of range.
    explicit Madgwick(const MadgwickConfig& config);

    // The start: up from the specific force, heading_of() = heading_rad.
    void align(int64_t t_ns, const Vec3& accel_body, double heading_rad);
    // The start given by the app (kept by the first update instead of align).
    void set_attitude(const Quat& q_enu_from_body);
    // Turns the attitude about the vertical so that heading_of() = heading_rad
    // (the tilt and the clock stay).
    void set_heading(double heading_rad);
    bool aligned() const { return aligned_; }
    bool started() const { return started_; }

    // One sample: IMU form with mag_body == nullptr, MARG form otherwise.
    // Returns false (and changes nothing) for a zero accelerometer reading.
    bool update(int64_t t_ns, const Vec3& gyro_radps, const Vec3& accel_body, const Vec3* mag_body);

    const Quat& q() const { return q_; }
    const Vec3& gyro_bias() const { return bias_; }
    // The unit up direction in the body frame (third row of R_enu_from_body).
    Vec3 up_body() const;
    void reset();

private:
    MadgwickConfig c_;
    double sin_decl_, cos_decl_;
    int64_t init_ns_;
    Quat q_ = Quat::Identity();
    Vec3 bias_ = Vec3::Zero();
    bool aligned_ = false, started_ = false;
    int64_t t_ns_ = 0, t0_ns_ = 0;
};

}  // namespace pednav::navmath
