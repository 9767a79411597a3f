// SPDX-License-Identifier: Apache-2.0
// Velocity/position mechanization of a foot-mounted IMU on top of an external
// attitude stream, with the 15-state error-state EKF (ekf15.hpp): ZUPT and
// ZARU during stance, HUPT at the stance after a level-floor step, error
// injection and reset, and per-stride segmentation.
//
// Per sample k (attitude q_k from the attitude estimator, already including
// every correction sent before k):
//   f_k   = R_k (k a_k - ba)                       specific force, ENU (k: accel
//                                                  scale, 1 unless accel_rescale_above)
//   v_k   = v_{k-1} + ((f_{k-1} + f_k)/2 - g) dt   mid-interval, cf. eq. (10)
//   p_k   = p_{k-1} + (v_{k-1} + v_k)/2 dt         cf. eq. (11)
// then P is propagated (eq. (32)) and, in stance, the measurements
//   ZUPT  z = v_roll - v_k     = dv + n     (eq. (34)-(35), velocity rows; v_roll =
//         h (w_enu x up), the sensor h above the sole of a foot rolling on the ground;
//         h = sensor_height_m, 0 gives the paper's z = 0 - v_k)
//   ZARU  z = w_k - bg         = dbg + n    (angular rate rows)
//   HUPT  z = h_ref - p_k,z    = dp_z + n   (foot-imu-height-update-hupt eq. (5);
//         after stairs h_ref is a level stood on before when one is near, level_memory.hpp)
// are applied as scalar updates; the estimate is injected (eq. (12)-(14) with
// this file's sign convention) and the error state reset to zero. The attitude
// and gyro-bias parts are returned as a correction for the attitude estimator.
#pragma once

#include <cstdint>

#include "ekf15.hpp"
#include "ekf15_dense.hpp"
#include "level_memory.hpp"

namespace pednav::zupt_ins {

// No defaults here: the foot EKF plugins' parameter schema holds them, with
// their ranges (pednav plugins --params); foot_ins_config() fills every field.
struct FootInsConfig {
    bool zupt;
    bool zaru;
    bool hupt;
    // Gravity subtracted in the mechanization; 0 = mean |a| over the first
    // stance (the vertical then holds for a sensor that reads off at rest).
    double gravity_mps2;
    // With gravity learned (gravity_mps2 0) and |a| at rest off
    // local_gravity_mps2 by more than this fraction, the accelerometer is
    // taken to have a scale error and rescaled to read local_gravity_mps2 at
    // rest: a sensor that reads 4.7 % high measures every stride 4.7 % long,
    // and the ZUPT cannot see it (the velocity still returns to zero). Within
    // it the reading is taken as gravity. At rest a bias along gravity looks
    // the same as a scale error, and rescaling a biased sensor makes its
    // strides wrong instead: 1 = never rescale (the preset), 0.02 = sensors
    // more than 2 % off (local gravity itself varies by 0.5 % over the Earth).
    double accel_rescale_above;
    double local_gravity_mps2;
    // Process noise densities.
    double gyro_noise_radps_per_sqrthz;
    double accel_noise_mps2_per_sqrthz;
    double gyro_bias_walk_radps_per_sqrts;
    double accel_bias_walk_mps2_per_sqrts;
    // Initial standard deviations.
    double init_roll_pitch_sd_rad;
    double init_heading_sd_rad;
    double init_gyro_bias_sd_radps;
    double init_accel_bias_sd_mps2;
    double init_velocity_sd_mps;
    // Measurement standard deviations.
    double zupt_sd_mps;
    double zaru_sd_radps;
    double zaru_max_radps;      // ZARU only while |w - bg| is below this (a rolling foot is not still)
    // ZARU also corrects the position (through its correlation with the gyro
    // bias); false = a consider update that holds the position estimate.
    bool zaru_moves_position;
    double zupt_lever_m;        // ZUPT sd grows by this times |w - bg| (sensor ahead of the pivot)
    // Height of the sensor above the sole: a stance foot rolling about its
    // contact point moves the sensor horizontally at (w x up) times this, and
    // the ZUPT expects that velocity instead of zero (0 = a plain ZUPT).
    double sensor_height_m;
    double hupt_sd_m;
    double level_match_m;       // a level reached after stairs within this of one stood on before is that level
    // Stride segmentation and level/stairs classification.
    double min_stance_s;        // shorter stances do not end a stride
    double min_swing_s;        // motion between counted stances
    double min_stride_m;        // horizontal displacement between counted stances
    double heel_strike_deg;    // toe-up pitch in the swing that marks a level step
    double max_dt_s;
    // The covariance propagation and the stance updates run at most at this
    // rate (the mechanization runs at every sample); 0 = at every sample.
    double filter_rate_hz;
    // In the swing (no measurements) the covariance transitions are multiplied
    // together and P is propagated once per this interval (Ekf15::defer_propagation),
    // and at the first filter step in stance (the first stance sample when
    // filter_rate_hz is 0); 0 = at every filter step. The per-sample position
    // covariance then holds during that interval.
    double swing_propagation_s;
    bool joseph_form;  // covariance update in Joseph form (else P - K H P)
};

// The config from named values: `v.number(key)` and `v.boolean(key)` for each
// field, by its name (a plugin's SDK Params, whose schema gives defaults and
// ranges; a test's values read from that schema).
template <class Values>
FootInsConfig foot_ins_config(Values& v) {
    FootInsConfig c;
    c.zupt = v.boolean("zupt");
    c.zaru = v.boolean("zaru");
    c.hupt = v.boolean("hupt");
    c.gravity_mps2 = v.number("gravity_mps2");
    c.accel_rescale_above = v.number("accel_rescale_above");
    c.local_gravity_mps2 = v.number("local_gravity_mps2");
    c.gyro_noise_radps_per_sqrthz = v.number("gyro_noise_radps_per_sqrthz");
    c.accel_noise_mps2_per_sqrthz = v.number("accel_noise_mps2_per_sqrthz");
    c.gyro_bias_walk_radps_per_sqrts = v.number("gyro_bias_walk_radps_per_sqrts");
    c.accel_bias_walk_mps2_per_sqrts = v.number("accel_bias_walk_mps2_per_sqrts");
    c.init_roll_pitch_sd_rad = v.number("init_roll_pitch_sd_rad");
    c.init_heading_sd_rad = v.number("init_heading_sd_rad");
    c.init_gyro_bias_sd_radps = v.number("init_gyro_bias_sd_radps");
    c.init_accel_bias_sd_mps2 = v.number("init_accel_bias_sd_mps2");
    c.init_velocity_sd_mps = v.number("init_velocity_sd_mps");
    c.zupt_sd_mps = v.number("zupt_sd_mps");
    c.zaru_sd_radps = v.number("zaru_sd_radps");
    c.zaru_max_radps = v.number("zaru_max_radps");
    c.zaru_moves_position = v.boolean("zaru_moves_position");
    c.zupt_lever_m = v.number("zupt_lever_m");
    c.sensor_height_m = v.number("sensor_height_m");
    c.hupt_sd_m = v.number("hupt_sd_m");
    c.level_match_m = v.number("level_match_m");
    c.min_stance_s = v.number("min_stance_s");
    c.min_swing_s = v.number("min_swing_s");
    c.min_stride_m = v.number("min_stride_m");
    c.heel_strike_deg = v.number("heel_strike_deg");
    c.max_dt_s = v.number("max_dt_s");
    c.filter_rate_hz = v.number("filter_rate_hz");
    c.swing_propagation_s = v.number("swing_propagation_s");
    c.joseph_form = v.boolean("joseph_form");
    return c;
}

struct StrideOut {
    int64_t t_start_ns;
    int64_t t_end_ns;
    Vec3 displacement;
    double heading_change_rad;
    double cov_xy[9];
    int stride_class;  // PN_STRIDE_CLASS_*
    int index;
};

struct SampleOut {
    Vec3 pos;
    Vec3 vel;
    double cov_pos[9];
    double heading_rad;
    bool correction = false;    // an update changed attitude or gyro bias
    Vec3 rot_enu_rad = Vec3::Zero();
    Vec3 gyro_bias_delta = Vec3::Zero();
    bool stride = false;        // `stride_out` holds a stride that ended at the previous sample
};

// Filter: the covariance algebra, Ekf15 (hand-written kernels, the plugin
// org.pednav.foot.ekf15) or Ekf15Dense (textbook dense Eigen, the reference
// plugin org.pednav.foot.ekf15.dense); both have the same interface.
template <class Filter>
class FootInsT {
public:
    explicit FootInsT(const FootInsConfig& c);

    // Start position and (when finite) start heading; the heading is applied
    // as a yaw correction at the first sample.
    void set_start(const Vec3& pos, double heading_rad);

    // One sample. `stance` is the detector decision for this sample.
    void step(int64_t t_ns, const Vec3& accel_mps2, const Vec3& gyro_radps, const Quat& q_enu_from_body,
              const Vec3& gyro_bias_radps, bool stance, SampleOut& out);

    // End of stream: the stride of a stance still open, if any.
    bool finish(StrideOut& s);

    const StrideOut& stride_out() const { return stride_; }

private:
    void stride_logic(int64_t t_ns, double dt, bool stance, const Quat& q, SampleOut& out);
    bool close_stance(StrideOut& s);
    void begin_stance(int64_t t_ns);

    FootInsConfig cfg_;
    double heel_strike_rad_;
    double skip_cos_half_;          // swing samples with |cos(angle/2) from the anchor| above this are not pitched
    Filter ekf_;
    Ekf15::Noise noise_;
    bool started_ = false;
    Vec3 start_pos_ = Vec3::Zero();
    double start_heading_ = NAN;
    Vec3 p_ = Vec3::Zero(), v_ = Vec3::Zero(), ba_ = Vec3::Zero();
    Vec3 f_prev_ = Vec3::Zero();
    int64_t t_prev_ = 0;
    double filter_dt_acc_ = 0.0;
    Vec3 filter_f_acc_ = Vec3::Zero();
    double g_ = 9.80665;            // gravity subtracted in the mechanization
    double accel_scale_ = 1.0;      // k: the mechanization and EKF use k a
    bool g_learning_ = false;
    double g_sum_ = 0, g_n_ = 0;

    // Stride state.
    bool in_stance_ = false;
    bool have_anchor_ = false;      // a counted stance exists
    int64_t stance_start_t_ = 0;
    int64_t last_t_ = 0;
    Vec3 last_stance_pos_ = Vec3::Zero();
    Quat last_stance_q_ = Quat::Identity();
    Vec3 anchor_pos_ = Vec3::Zero();     // position at the end of the last counted stance
    double anchor_heading_ = 0;
    int64_t anchor_t_ = 0;
    Quat anchor_q_ = Quat::Identity();
    double anchor_cov_[3] = {0, 0, 0};
    double moving_s_ = 0;           // motion time since the last counted stance
    double max_toe_up_rad_ = 0;     // largest toe-up pitch since the last counted stance, as far as
                                    // needed to tell whether it reaches heel_strike_deg
    bool level_step_ = true;        // class of the step that led to the current stance
    double h_ref_ = 0;              // HUPT reference height
    LevelMemory levels_;            // heights of the level floors stood on
    int stride_index_ = 0;
    StrideOut stride_{};
};

using FootIns = FootInsT<Ekf15>;
using FootInsDense = FootInsT<Ekf15Dense>;
extern template class FootInsT<Ekf15>;
extern template class FootInsT<Ekf15Dense>;

}  // namespace pednav::zupt_ins
