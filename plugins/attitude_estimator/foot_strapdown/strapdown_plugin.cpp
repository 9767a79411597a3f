// Foot strapdown attitude estimator: alignment on the opening still period,
// then bias-compensated attitude integration with mid-interval rates; applies
// the position filter's ATTITUDE_CORRECTION before the next sample.
//
// Start heading: without a trusted magnetometer the heading comes from
// initial_heading_deg. A heading given to the engine reaches this plugin from
// the position filter (set_start) as a yaw ATTITUDE_CORRECTION at the first
// sample, the same path as every other correction.
#include <pednav_navmath/heading.hpp>
#include <pednav_navmath/strapdown.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
using pednav::navmath::Quat;
using pednav::navmath::Vec3;

class FootStrapdown : public AttitudeEstimator {
public:
    static constexpr const char* kId = "org.pednav.foot.strapdown";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:foot", "uses:mag", nullptr};
    static constexpr const char* kName = "foot strapdown attitude";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "still-period alignment (accelerometer, tilt-compensated magnetometer), rotation-vector attitude "
        "integration with mid-interval rates and coning term, EKF feedback";
    static constexpr uint64_t kConsumes =
        PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_MAG) | PN_REC_MASK(PN_REC_ATTITUDE_CORRECTION);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_ATTITUDE);

    FootStrapdown(Params& p, const CreateContext&) : sd_(read(p)) {}

    void on_imu(const pn_imu_t& imu) override {
        const Vec3 a(imu.accel_mps2[0], imu.accel_mps2[1], imu.accel_mps2[2]);
        const Vec3 w(imu.gyro_radps[0], imu.gyro_radps[1], imu.gyro_radps[2]);
        if (!std::isfinite(a.sum()) || !std::isfinite(w.sum())) throw InputError("non-finite IMU sample");
        if (!sd_.on_imu(imu.header.t_ns, a, w)) return;
        auto r = make_record<pn_attitude_t>(imu.header.t_ns);
        const Quat& q = sd_.q();
        r.q_enu_from_body[0] = q.w();
        r.q_enu_from_body[1] = q.x();
        r.q_enu_from_body[2] = q.y();
        r.q_enu_from_body[3] = q.z();
        r.heading_rad = pednav::navmath::heading_of(q);
        for (int i = 0; i < 3; ++i) r.gyro_bias_radps[i] = sd_.gyro_bias()[i];
        emit(r);
    }
    void on_mag(const pn_mag_t& m) override {
        sd_.on_mag(m.header.t_ns, Vec3(m.mag_ut[0], m.mag_ut[1], m.mag_ut[2]));
    }
    void on_attitude_correction(const pn_attitude_correction_t& c) override {
        sd_.apply_correction(Vec3(c.rotation_enu_rad[0], c.rotation_enu_rad[1], c.rotation_enu_rad[2]),
                             Vec3(c.gyro_bias_delta_radps[0], c.gyro_bias_delta_radps[1], c.gyro_bias_delta_radps[2]));
    }
    bool set_attitude(int64_t, const double q[4]) override {
        sd_.set_attitude(Quat(q[0], q[1], q[2], q[3]));
        return true;
    }

private:
    static pednav::navmath::StrapdownConfig read(Params& p) {
        pednav::navmath::StrapdownConfig c;
        c.align_still_s = p.number("align_still_s", c.align_still_s, 0.0, 600.0);
        c.align_min_still_s = p.number("align_min_still_s", c.align_min_still_s, 0.0, 600.0);
        c.align_timeout_s = p.number("align_timeout_s", c.align_timeout_s, 0.0, 3600.0);
        c.align_gyro_max_radps = p.number("align_gyro_max_radps", c.align_gyro_max_radps, 0.0, 10.0);
        c.align_accel_dev_mps2 = p.number("align_accel_dev_mps2", c.align_accel_dev_mps2, 0.0, 50.0);
        c.use_magnetometer = p.boolean("use_magnetometer", c.use_magnetometer);
        c.mag_min_ut = p.number("mag_min_ut", c.mag_min_ut, 0.0, 1000.0);
        c.mag_max_ut = p.number("mag_max_ut", c.mag_max_ut, 0.0, 1000.0);
        c.declination_deg = p.number("declination_deg", c.declination_deg, -180.0, 180.0);
        c.initial_heading_deg = p.number("initial_heading_deg", c.initial_heading_deg, -360.0, 360.0);
        c.gyro_bias_from_still = p.boolean("gyro_bias_from_still", c.gyro_bias_from_still);
        c.bias_still_max_sd_radps = p.number("bias_still_max_sd_radps", c.bias_still_max_sd_radps, 0.0, 10.0);
        c.coning = p.boolean("coning", c.coning);
        c.max_dt_s = p.number("max_dt_s", c.max_dt_s, 1e-4, 10.0);
        c.gyro_range_radps = p.number("gyro_range_radps", c.gyro_range_radps, 0.0, 1000.0);
        return c;
    }

    pednav::navmath::Strapdown sd_;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.foot.strapdown", "1.0.0", FootStrapdown)
