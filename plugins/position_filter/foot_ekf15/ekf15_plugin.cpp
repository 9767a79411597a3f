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

    static pednav::zupt_ins::FootInsConfig read(Params& p) {
        pednav::zupt_ins::FootInsConfig c;
        c.zupt = p.boolean("zupt", c.zupt);
        c.zaru = p.boolean("zaru", c.zaru);
        c.hupt = p.boolean("hupt", c.hupt);
        c.gravity_mps2 = p.number("gravity_mps2", c.gravity_mps2, 0.0, 20.0);
        c.accel_rescale_above = p.number("accel_rescale_above", c.accel_rescale_above, 0.0, 1.0);
        c.local_gravity_mps2 = p.number("local_gravity_mps2", c.local_gravity_mps2, 9.7, 9.9);
        c.gyro_noise_radps_per_sqrthz = p.number("gyro_noise_radps_per_sqrthz", c.gyro_noise_radps_per_sqrthz, 0.0, 10.0);
        c.accel_noise_mps2_per_sqrthz = p.number("accel_noise_mps2_per_sqrthz", c.accel_noise_mps2_per_sqrthz, 0.0, 100.0);
        c.gyro_bias_walk_radps_per_sqrts =
            p.number("gyro_bias_walk_radps_per_sqrts", c.gyro_bias_walk_radps_per_sqrts, 0.0, 10.0);
        c.accel_bias_walk_mps2_per_sqrts =
            p.number("accel_bias_walk_mps2_per_sqrts", c.accel_bias_walk_mps2_per_sqrts, 0.0, 100.0);
        c.init_roll_pitch_sd_rad = p.number("init_roll_pitch_sd_rad", c.init_roll_pitch_sd_rad, 0.0, 4.0);
        c.init_heading_sd_rad = p.number("init_heading_sd_rad", c.init_heading_sd_rad, 0.0, 4.0);
        c.init_gyro_bias_sd_radps = p.number("init_gyro_bias_sd_radps", c.init_gyro_bias_sd_radps, 0.0, 10.0);
        c.init_accel_bias_sd_mps2 = p.number("init_accel_bias_sd_mps2", c.init_accel_bias_sd_mps2, 0.0, 100.0);
        c.init_velocity_sd_mps = p.number("init_velocity_sd_mps", c.init_velocity_sd_mps, 0.0, 100.0);
        c.zupt_sd_mps = p.number("zupt_sd_mps", c.zupt_sd_mps, 1e-6, 100.0);
        c.zaru_sd_radps = p.number("zaru_sd_radps", c.zaru_sd_radps, 1e-6, 100.0);
        c.zaru_max_radps = p.number("zaru_max_radps", c.zaru_max_radps, 0.0, 100.0);
        c.zaru_moves_position = p.boolean("zaru_moves_position", c.zaru_moves_position);
        c.zupt_lever_m = p.number("zupt_lever_m", c.zupt_lever_m, 0.0, 10.0);
        c.sensor_height_m = p.number("sensor_height_m", c.sensor_height_m, 0.0, 0.5);
        c.hupt_sd_m = p.number("hupt_sd_m", c.hupt_sd_m, 1e-6, 100.0);
        c.level_match_m = p.number("level_match_m", c.level_match_m, 0.0, 10.0);
        c.min_stance_s = p.number("min_stance_s", c.min_stance_s, 0.0, 10.0);
        c.min_swing_s = p.number("min_swing_s", c.min_swing_s, 0.0, 10.0);
        c.min_stride_m = p.number("min_stride_m", c.min_stride_m, 0.0, 10.0);
        c.heel_strike_deg = p.number("heel_strike_deg", c.heel_strike_deg, 0.0, 90.0);
        c.max_dt_s = p.number("max_dt_s", c.max_dt_s, 1e-4, 10.0);
        c.filter_rate_hz = p.number("filter_rate_hz", c.filter_rate_hz, 0.0, 10000.0);
        c.swing_propagation_s = p.number("swing_propagation_s", c.swing_propagation_s, 0.0, 1.0);
        c.joseph_form = p.boolean("joseph_form", c.joseph_form);
        return c;
    }

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
        "dense H): the same track to round-off at about 17 times the instructions of the three foot plugins; a "
        "reference for checks and benchmarks";
    using FootInsFilter::FootInsFilter;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.foot.ekf15", "1.0.0", FootEkf15, FootEkf15Dense)
