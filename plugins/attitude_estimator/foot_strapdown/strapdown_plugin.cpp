// SPDX-License-Identifier: Apache-2.0
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
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "align_still_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 600, "default": 1.0,
      "description": "still time that triggers the alignment"},
    "align_min_still_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 600, "default": 0.3,
      "description": "shortest still period accepted for the alignment when motion starts"},
    "align_timeout_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 3600, "default": 10,
      "description": "align on the current sample after this long without a still period"},
    "align_gyro_max_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 10, "default": 0.35,
      "description": "still: |w| below this"},
    "align_accel_dev_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0, "maximum": 50, "default": 0.6,
      "description": "still: |a - mean a| below this"},
    "use_magnetometer": {"type": "boolean", "default": true,
      "description": "initial heading from a trusted magnetometer (field strength within mag_min_ut to mag_max_ut)"},
    "mag_min_ut": {"type": "number", "x-unit": "uT", "minimum": 0, "maximum": 1000, "default": 15,
      "description": "weaker fields are not trusted; at most mag_max_ut"},
    "mag_max_ut": {"type": "number", "x-unit": "uT", "minimum": 0, "maximum": 1000, "default": 100,
      "description": "stronger fields are not trusted; at least mag_min_ut"},
    "declination_deg": {"type": "number", "x-unit": "deg", "minimum": -180, "maximum": 180, "default": 0,
      "description": "magnetic declination, east positive: true heading = magnetic + declination"},
    "initial_heading_deg": {"type": "number", "x-unit": "deg", "minimum": -360, "maximum": 360, "default": 0,
      "description": "heading without a trusted magnetometer, clockwise from north"},
    "gyro_bias_from_still": {"type": "boolean", "default": true,
      "description": "initial gyro bias = mean rate over the alignment's still period, when its sd is below bias_still_max_sd_radps"},
    "bias_still_max_sd_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 10, "default": 0.01,
      "description": "the still period gives the initial gyro bias (gyro_bias_from_still) only when the rate's sd over it is below this (truly still)"},
    "coning": {"type": "boolean", "default": true,
      "description": "second-order coning term in the rotation vector"},
    "max_dt_s": {"type": "number", "x-unit": "s", "minimum": 1e-4, "maximum": 10, "default": 0.1,
      "description": "longer gaps between samples are integrated as this"},
    "gyro_range_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 1000, "default": 0,
      "description": "the gyro's full-scale range: clipped runs (>= 99.5 % of it) get their missing rotation restored; 0 = off (a property of the sensor, not a tuning constant)"}
  }
})json";
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
        const pednav::navmath::StrapdownConfig c = pednav::navmath::strapdown_config(p);
        if (c.mag_min_ut > c.mag_max_ut)
            Params::fail("mag_min_ut", "is " + format_number(c.mag_min_ut) + " uT, above mag_max_ut (" +
                                           format_number(c.mag_max_ut) + " uT): no field would be trusted");
        return c;
    }

    pednav::navmath::Strapdown sd_;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.foot.strapdown", "1.0.0", FootStrapdown)
