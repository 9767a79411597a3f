// SPDX-License-Identifier: Apache-2.0
// Waist (belt) attitude estimator: quaternion strapdown with the 9-state
// error EKF of pednav_attitude_ekf (attitude, gyro bias, accelerometer bias,
// and the magnetometer's compass deviation), one PN_REC_ATTITUDE per IMU
// sample once aligned. Yaw from the magnetometer while its field agrees with
// the local one
// (PN_ATTITUDE_FLAG_MAG_USED on the records after a correction), else the
// config's initial heading, a GNSS course, or the app (set_attitude).
#include <cmath>

#include <pednav_attitude_ekf/attitude_ekf.hpp>
#include <pednav_navmath/heading.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
using pednav::attitude_ekf::AttitudeEkf;
using pednav::navmath::Quat;
using pednav::navmath::Vec3;

class WaistAttitudeEkf : public AttitudeEstimator {
public:
    static constexpr const char* kId = "org.pednav.waist.attitude.ekf9";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:waist", "uses:mag", "uses:gnss", nullptr};
    static constexpr const char* kName = "waist attitude, 9-state error EKF and compass deviation";
    static constexpr const char* kVersion = "1.1.0";
    static constexpr const char* kDescription =
        "quaternion strapdown, error EKF of attitude, gyro bias and accelerometer bias (waist paper sec. 4.2-4.3, "
        "eq. 4.2-4.10): roll and pitch from gravity, gyro bias from still periods, heading from a gated "
        "magnetometer whose hard-iron compass deviation is estimated as the walker turns; no gyrocompassing";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "align_still_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 600, "default": 1.0,
      "description": "still time that triggers the alignment (roll, pitch, gyro bias, yaw)"},
    "align_timeout_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 3600, "default": 5.0,
      "description": "align on the mean specific force after this long without a still period"},
    "still_gyro_max_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 10, "default": 0.05,
      "description": "still: the bias-compensated rate's norm below this"},
    "still_accel_dev_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 10, "default": 0.3,
      "description": "still: ||a| - g| below this"},
    "gyro_noise_radps_per_sqrthz": {"type": "number", "x-unit": "rad/s/sqrt(Hz)", "minimum": 0, "maximum": 1, "default": 0.002,
      "description": "angle random walk (Q of dphi, eq. 4.9)"},
    "gyro_bias_walk_radps_per_sqrts": {"type": "number", "x-unit": "rad/s/sqrt(s)", "minimum": 0, "maximum": 1, "default": 0.0001,
      "description": "gyro bias random walk (Q of dbg)"},
    "accel_bias_walk_mps2_per_sqrts": {"type": "number", "x-unit": "m/s^2/sqrt(s)", "minimum": 0, "maximum": 10, "default": 0.001,
      "description": "accelerometer bias random walk (Q of dba)"},
    "init_tilt_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.05,
      "description": "P0 of dphi_E, dphi_N"},
    "init_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.5,
      "description": "P0 of dphi_U"},
    "init_gyro_bias_sd_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 10, "default": 0.01,
      "description": "P0 of dbg"},
    "init_accel_bias_sd_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "P0 of dba"},
    "gravity_update_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 60, "default": 1.0,
      "description": "one gravity (roll, pitch) update per window of this long: its mean specific force in ENU has no horizontal part"},
    "gravity_sd_quiet_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 1e-6, "maximum": 100, "default": 0.05,
      "description": "sd of the window's mean horizontal specific force when |a| is quiet"},
    "gravity_sd_moving_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 1e-6, "maximum": 100, "default": 0.3,
      "description": "the same while walking (a window is rarely a whole number of steps)"},
    "quiet_accel_sd_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 100, "default": 0.2,
      "description": "a window is quiet when the sd of |a| over it is below this"},
    "still_bias_sd_radps": {"type": "number", "x-unit": "rad/s", "minimum": 1e-9, "maximum": 1, "default": 0.002,
      "description": "sd of a still window's mean rate as the gyro bias"},
    "use_magnetometer": {"type": "boolean", "default": true,
      "description": "heading from the magnetometer while mag_* accept its field"},
    "declination_deg": {"type": "number", "x-unit": "deg", "minimum": -180, "maximum": 180, "default": 0,
      "description": "magnetic declination, east positive: true heading = magnetic + declination"},
    "mag_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 1e-6, "maximum": 4, "default": 0.2,
      "description": "sd of one magnetometer heading after the deviation; large because what is left (nearby steel, soft iron) is correlated from one update to the next: the gyro carries the heading between, the magnetometer holds it over minutes"},
    "mag_deviation_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 1, "default": 0.05,
      "description": "P0 of the compass deviation B sin(psi) + C cos(psi) of the sensor's own hard-iron field (B and C are estimated as the walker turns); 0 = not estimated"},
    "mag_deviation_walk_rad_per_sqrts": {"type": "number", "x-unit": "rad/sqrt(s)", "minimum": 0, "maximum": 1, "default": 0.0001,
      "description": "random walk of B and C (the sensor's magnetisation and its tilt on the belt change)"},
    "mag_update_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 60, "default": 0.5,
      "description": "at most one magnetometer update per this long (its errors are correlated in time)"},
    "mag_gate_chi2": {"type": "number", "minimum": 0.01, "maximum": 1e6, "default": 9,
      "description": "a magnetometer heading whose normalised innovation squared is above this is rejected (a disturbance the field gate let through)"},
    "mag_max_rejections": {"type": "integer", "minimum": 1, "maximum": 100000, "default": 20,
      "description": "this many rejected magnetometer headings in a row mean the heading is wrong: the next one resets it"},
    "mag_field_ut": {"type": "number", "x-unit": "uT", "minimum": 0, "maximum": 200, "default": 0,
      "description": "local field strength; 0 = learn it over mag_learn_s"},
    "mag_dip_deg": {"type": "number", "x-unit": "deg", "minimum": -1000, "maximum": 90, "default": -1000,
      "description": "local dip, down positive; below -90 = learn it"},
    "mag_field_tolerance_ut": {"type": "number", "x-unit": "uT", "minimum": 0.01, "maximum": 200, "default": 5,
      "description": "accepted |strength - local|"},
    "mag_dip_tolerance_deg": {"type": "number", "x-unit": "deg", "minimum": 0.01, "maximum": 180, "default": 5,
      "description": "accepted |dip - local|"},
    "mag_learn_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 3600, "default": 5,
      "description": "the local field is the median over this long of readings (when not configured)"},
    "initial_heading_deg": {"type": "number", "x-unit": "deg", "minimum": -360, "maximum": 360, "default": 0,
      "description": "yaw without magnetometer, GNSS course or app, clockwise from north"},
    "gnss_course_min_speed_mps": {"type": "number", "x-unit": "m/s", "minimum": 0, "maximum": 50, "default": 0.8,
      "description": "until the magnetometer or the app gives the yaw, a GNSS course at this speed or faster sets it (the sensor's heading taken as the walking direction); 0 = never"},
    "max_dt_s": {"type": "number", "x-unit": "s", "minimum": 1e-4, "maximum": 10, "default": 0.1,
      "description": "longer gaps between samples are integrated as this"}
  }
})json";
    static constexpr uint64_t kConsumes =
        PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_MAG) | PN_REC_MASK(PN_REC_GNSS);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_ATTITUDE);

    WaistAttitudeEkf(Params& p, const CreateContext&) : ekf_(pednav::attitude_ekf::attitude_ekf_config(p)) {}

    void on_imu(const pn_imu_t& imu) override {
        const Vec3 a(imu.accel_mps2[0], imu.accel_mps2[1], imu.accel_mps2[2]);
        const Vec3 w(imu.gyro_radps[0], imu.gyro_radps[1], imu.gyro_radps[2]);
        if (!ekf_.on_imu(imu.header.t_ns, a, w)) return;
        auto r = make_record<pn_attitude_t>(imu.header.t_ns);
        const Quat& q = ekf_.q();
        r.q_enu_from_body[0] = q.w();
        r.q_enu_from_body[1] = q.x();
        r.q_enu_from_body[2] = q.y();
        r.q_enu_from_body[3] = q.z();
        r.heading_rad = pednav::navmath::heading_of(q);
        for (int i = 0; i < 3; ++i) r.gyro_bias_radps[i] = ekf_.gyro_bias()[i];
        const Eigen::Matrix3d P = ekf_.attitude_cov();
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) r.cov_attitude_rad2[3 * i + j] = 0.5 * (P(i, j) + P(j, i));
        if (ekf_.take_mag_used()) r.header.flags |= PN_ATTITUDE_FLAG_MAG_USED;
        emit(r);
    }
    void on_mag(const pn_mag_t& m) override {
        ekf_.on_mag(m.header.t_ns, Vec3(m.mag_ut[0], m.mag_ut[1], m.mag_ut[2]));
    }
    void on_gnss(const pn_gnss_t& g) override {
        if (!(g.header.flags & PN_GNSS_FLAG_HAS_VELOCITY)) return;
        const double ve = g.vel_enu_mps[0], vn = g.vel_enu_mps[1];
        ekf_.on_gnss_course(std::atan2(ve, vn), std::hypot(ve, vn));
    }
    bool set_attitude(int64_t, const double q[4]) override {
        ekf_.set_attitude(Quat(q[0], q[1], q[2], q[3]));
        return true;
    }

private:
    AttitudeEkf ekf_;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.waist.attitude", "1.1.0", WaistAttitudeEkf)
