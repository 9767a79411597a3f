// SPDX-License-Identifier: Apache-2.0
// Foot position filter: velocity/position mechanization on the attitude
// stream, 15-state error-state EKF with ZUPT, ZARU and HUPT, one position per
// IMU sample, one stride per stance, attitude/gyro-bias feedback.
#include <cmath>

#include <pednav_sdk/library.hpp>
#include <pednav_sdk/time_join.hpp>
#include <pednav_zupt_ins/foot_ins.hpp>

namespace {
using namespace pednav::sdk;
using pednav::navmath::Quat;
using pednav::navmath::Vec3;

// The foot INS as a position filter, over either covariance algebra (Ins is
// FootIns or FootInsDense); the two plugins below differ only in their ids.
template <class Ins>
class FootInsFilter : public PositionFilter {
    // The IMU sample, its gait phase and its attitude.
    using Join = TimeJoin<pn_imu_t, pn_gait_phase_t, pn_attitude_t>;

public:
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:foot", "needs:gait_phase", "needs:attitude", nullptr};
    static constexpr uint64_t kConsumes = Join::kRecordMask;
    static constexpr uint64_t kProduces =
        PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_ATTITUDE_CORRECTION);
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "zupt": {"type": "boolean", "default": true, "description": "zero-velocity update in stance"},
    "zaru": {"type": "boolean", "default": true, "description": "zero angular rate update in stance"},
    "hupt": {"type": "boolean", "default": true, "description": "height update after a level-floor step"},
    "gravity_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 20, "default": 0,
      "description": "gravity subtracted in the mechanization; 0 = mean |a| over the first stance (the vertical then holds for a sensor that reads off at rest)"},
    "accel_rescale_above": {"type": "number", "minimum": 0, "maximum": 1, "default": 1,
      "description": "with gravity learned: when |a| over the first stance is off local_gravity_mps2 by more than this fraction, the accelerometer is rescaled to read local_gravity_mps2 at rest (a scale error lengthens or shortens every stride, and ZUPT cannot see it); within it the reading is taken as gravity. A bias along gravity looks the same at rest, and rescaling it makes the strides wrong; 0 = always, 1 = never"},
    "local_gravity_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 9.7, "maximum": 9.9, "default": 9.80665,
      "description": "gravity where the walk is (9.78 at the equator to 9.83 at the poles); used by accel_rescale_above"},
    "gyro_noise_radps_per_sqrthz": {"type": "number", "x-unit": "rad/s/sqrt(Hz)", "minimum": 0, "maximum": 10, "default": 0.002,
      "description": "angle random walk density (Q of phi)"},
    "accel_noise_mps2_per_sqrthz": {"type": "number", "x-unit": "m/s^2/sqrt(Hz)", "minimum": 0, "maximum": 100, "default": 0.2,
      "description": "velocity random walk density (Q of dv)"},
    "gyro_bias_walk_radps_per_sqrts": {"type": "number", "x-unit": "rad/s/sqrt(s)", "minimum": 0, "maximum": 10, "default": 1e-5,
      "description": "gyro bias random walk (Q of dbg)"},
    "accel_bias_walk_mps2_per_sqrts": {"type": "number", "x-unit": "m/s^2/sqrt(s)", "minimum": 0, "maximum": 100, "default": 1e-3,
      "description": "accel bias random walk (Q of dba)"},
    "init_roll_pitch_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.02,
      "description": "P0 of phi_x, phi_y"},
    "init_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0,
      "description": "P0 of phi_z (heading is a reference)"},
    "init_gyro_bias_sd_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 10, "default": 0.001,
      "description": "P0 of dbg"},
    "init_accel_bias_sd_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 100, "default": 0.1,
      "description": "P0 of dba"},
    "init_velocity_sd_mps": {"type": "number", "x-unit": "m/s", "minimum": 0, "maximum": 100, "default": 0.01,
      "description": "P0 of dv"},
    "zupt_sd_mps": {"type": "number", "x-unit": "m/s", "minimum": 1e-6, "maximum": 100, "default": 0.01,
      "description": "ZUPT noise sd at rest"},
    "zupt_lever_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.3,
      "description": "ZUPT sd grows by this x |w - bg| (sensor ahead of the pivot)"},
    "sensor_height_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 0.5, "default": 0.05,
      "description": "height of the sensor above the sole: the ZUPT expects the velocity of a foot rolling on its contact point, h (w x up), instead of zero; 0 = the paper's ZUPT"},
    "zaru_sd_radps": {"type": "number", "x-unit": "rad/s", "minimum": 1e-6, "maximum": 100, "default": 0.02,
      "description": "ZARU noise sd"},
    "zaru_max_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 100, "default": 0.1,
      "description": "ZARU only while |w - bg| is below this (a rolling foot is not still)"},
    "zaru_moves_position": {"type": "boolean", "default": true,
      "description": "ZARU also corrects the position (through the bias-position correlation); false = its gain on the position errors is zero (a consider update, Joseph form), which keeps a standing foot that sways from being moved (see Weak points in docs/foot-pipeline.md)"},
    "hupt_sd_m": {"type": "number", "x-unit": "m", "minimum": 1e-6, "maximum": 100, "default": 0.01,
      "description": "HUPT noise sd"},
    "level_match_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "after stairs, a level within this of one stood on before is that level, and HUPT holds it at that height (level memory); 0 = off"},
    "min_stance_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 10, "default": 0,
      "description": "shorter stances do not close a stride"},
    "min_swing_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 10, "default": 0.15,
      "description": "motion time between counted stances"},
    "min_stride_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.2,
      "description": "horizontal motion between counted stances"},
    "heel_strike_deg": {"type": "number", "x-unit": "deg", "minimum": 0, "maximum": 90, "default": 12,
      "description": "toe-up pitch in the swing that marks a level step"},
    "max_dt_s": {"type": "number", "x-unit": "s", "minimum": 1e-4, "maximum": 10, "default": 0.1,
      "description": "longer gaps between samples are integrated as this"},
    "filter_rate_hz": {"type": "number", "x-unit": "Hz", "minimum": 0, "maximum": 10000, "default": 0,
      "description": "covariance propagation and stance updates at most at this rate (mechanization stays per sample); 0 = every sample"},
    "swing_propagation_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 1, "default": 0.1,
      "description": "in the swing (no measurements) the transitions are multiplied together and the covariance propagated once per this interval, and at the first filter step in stance, with the summed process noise half before and half after; the per-sample position covariance holds in between; 0 = every filter step"},
    "joseph_form": {"type": "boolean", "default": true,
      "description": "covariance update in Joseph form (eq. (33)); false = P - K H P, equal for the optimal gain, a third of the arithmetic"}
  }
})json";

    FootInsFilter(Params& p, const CreateContext&) : ins_(read(p)) {}

    // A sample is processed once its IMU record, gait phase and attitude are
    // all in, in any order; without a gait phase for it (no step detector),
    // when the next sample's first record arrives or at flush (TimeJoin).
    void on_imu(const pn_imu_t& imu) override { join_.add(imu, step()); }
    void on_gait_phase(const pn_gait_phase_t& g) override { join_.add(g, step()); }
    void on_attitude(const pn_attitude_t& att) override { join_.add(att, step()); }
    void on_flush() override {
        join_.flush(step());
        pednav::zupt_ins::StrideOut s;
        if (ins_.finish(s)) emit_stride(s);
    }
    bool set_start(const double pos[3], double heading_rad) override {
        ins_.set_start(Vec3(pos[0], pos[1], pos[2]), heading_rad);
        return true;
    }

private:
    auto step() {
        return [this](const Join::Sample& s) { process(s); };
    }
    // One IMU sample with its attitude; without a gait phase it is not
    // stance. Without an attitude (the estimator is still aligning) there is
    // nothing to integrate, nor without an IMU record (an attitude at a time
    // of its own).
    void process(const Join::Sample& sample) {
        const pn_imu_t* imu = sample.get<pn_imu_t>();
        const pn_attitude_t* attitude = sample.get<pn_attitude_t>();
        if (!imu || !attitude) return;
        const pn_attitude_t& att = *attitude;
        const pn_gait_phase_t* gait = sample.get<pn_gait_phase_t>();
        const int64_t t = att.header.t_ns;
        const Vec3 a(imu->accel_mps2[0], imu->accel_mps2[1], imu->accel_mps2[2]);
        const Vec3 w(imu->gyro_radps[0], imu->gyro_radps[1], imu->gyro_radps[2]);
        const Quat q(att.q_enu_from_body[0], att.q_enu_from_body[1], att.q_enu_from_body[2],
                     att.q_enu_from_body[3]);
        const Vec3 bg(att.gyro_bias_radps[0], att.gyro_bias_radps[1], att.gyro_bias_radps[2]);
        const bool stance = gait && gait->stance != 0;
        ins_.step(t, a, w, q, bg, stance, out_);
        if (!std::isfinite(out_.pos.sum()) || !std::isfinite(out_.vel.sum()))
            throw NumericError("foot INS diverged (non-finite position)");
        if (out_.stride) emit_stride(ins_.stride_out());
        auto r = make_record<pn_position_t>(t);
        r.header.flags = PN_POSITION_FLAG_HAS_VELOCITY;
        for (int i = 0; i < 3; ++i) {
            r.pos_enu_m[i] = out_.pos[i];
            r.vel_enu_mps[i] = out_.vel[i];
        }
        for (int i = 0; i < 9; ++i) r.cov_enu_m2[i] = out_.cov_pos[i];
        r.heading_rad = out_.heading_rad;
        r.source = PN_POSITION_SOURCE_INERTIAL;
        emit(r);
        if (out_.correction) {
            auto c = make_record<pn_attitude_correction_t>(t);
            for (int i = 0; i < 3; ++i) {
                c.rotation_enu_rad[i] = out_.rot_enu_rad[i];
                c.gyro_bias_delta_radps[i] = out_.gyro_bias_delta[i];
            }
            emit(c);
        }
    }
    void emit_stride(const pednav::zupt_ins::StrideOut& s) {
        auto r = make_record<pn_stride_t>(s.t_end_ns);
        r.t_start_ns = s.t_start_ns;
        for (int i = 0; i < 3; ++i) r.displacement_enu_m[i] = s.displacement[i];
        r.length_m = std::hypot(s.displacement.x(), s.displacement.y());
        r.heading_change_rad = s.heading_change_rad;
        for (int i = 0; i < 9; ++i) r.cov_displacement_m2[i] = s.cov_xy[i];
        r.stride_class = s.stride_class;
        r.index = s.index;
        emit(r);
    }

    static pednav::zupt_ins::FootInsConfig read(Params& p) { return pednav::zupt_ins::foot_ins_config(p); }

    Ins ins_;
    pednav::zupt_ins::SampleOut out_;
    Join join_;
};

class FootEkf15 : public FootInsFilter<pednav::zupt_ins::FootIns> {
public:
    static constexpr const char* kId = "org.pednav.foot.ekf15";
    static constexpr const char* kName = "foot INS, 15-state error-state EKF";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "mid-interval velocity/position mechanization, error-state EKF [attitude, gyro bias, position, velocity, "
        "accel bias] with ZUPT, ZARU (foot-imu-zupt-zaru-ekf) and HUPT (foot-imu-height-update-hupt)";
    using FootInsFilter::FootInsFilter;
};

class FootEkf15Dense : public FootInsFilter<pednav::zupt_ins::FootInsDense> {
public:
    static constexpr const char* kId = "org.pednav.foot.ekf15.dense";
    static constexpr const char* kName = "foot INS, 15-state error-state EKF, dense reference";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "org.pednav.foot.ekf15 with textbook dense covariance algebra (15 x 15 Phi P Phi^T, Joseph form with a "
        "dense H): the same track to round-off at about 16 times the instructions of the three foot plugins; a "
        "reference for checks and benchmarks";
    using FootInsFilter::FootInsFilter;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.foot.ekf15", "1.0.0", FootEkf15, FootEkf15Dense)
