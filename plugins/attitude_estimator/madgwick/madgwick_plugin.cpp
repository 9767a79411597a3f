// SPDX-License-Identifier: Apache-2.0
// Madgwick's gradient-descent attitude filter (navmath::Madgwick) as an
// attitude estimator: one PN_REC_ATTITUDE per IMU sample. In the MARG form
// the newest magnetometer reading corrects the attitude only while
// navmath::MagneticFieldGate accepts it (strength and dip agree with the local
// field) and it is at most mag_max_age_s old; such records carry
// PN_ATTITUDE_FLAG_MAG_USED.
//
// Start: up from the first accelerometer reading, heading initial_heading_deg,
// or the attitude the app gives (set_attitude). In the MARG form the first
// accepted magnetometer reading within init_s sets the heading at once
// (tilt-compensated, plus the declination); attitudes are emitted from then
// on (or from init_s without one).
#include <cmath>

#include <pednav_navmath/alignment.hpp>
#include <pednav_navmath/heading.hpp>
#include <pednav_navmath/madgwick.hpp>
#include <pednav_navmath/magnetic_field_gate.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
using pednav::navmath::Quat;
using pednav::navmath::Vec3;

class MadgwickAttitude : public AttitudeEstimator {
public:
    static constexpr const char* kId = "org.pednav.pdr.madgwick";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:chest", "mount:handheld", "uses:mag", nullptr};
    static constexpr const char* kName = "Madgwick attitude (IMU and MARG)";
    static constexpr const char* kVersion = "1.0.0";
    static constexpr const char* kDescription =
        "Madgwick's gradient-descent filter (2010/2011) in ENU, IMU or MARG form, the magnetometer used only "
        "while its strength and dip agree with the local field; gyro bias gain zeta";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "form": {"type": "string", "enum": ["marg", "imu"], "default": "marg",
      "description": "marg: gyro, accelerometer and (gated) magnetometer; imu: gyro and accelerometer only"},
    "gain_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 10, "default": 0.04,
      "description": "beta: the gradient step's rate (Madgwick: sqrt(3/4) x the gyro's measurement error)"},
    "gyro_bias_gain_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 1, "default": 0,
      "description": "zeta: rate of the gyro bias estimate from the gradient; 0 = none"},
    "init_gain_radps": {"type": "number", "x-unit": "rad/s", "minimum": 0, "maximum": 20, "default": 1.0,
      "description": "beta during the first init_s, for a fast start"},
    "init_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 60, "default": 1.0,
      "description": "duration of the start gain; in the MARG form the first accepted magnetometer reading within it sets the heading"},
    "initial_heading_deg": {"type": "number", "x-unit": "deg", "minimum": -360, "maximum": 360, "default": 0,
      "description": "start heading of the body x axis (heading_rad of the records), clockwise from north, without a magnetometer or an app attitude"},
    "declination_deg": {"type": "number", "x-unit": "deg", "minimum": -180, "maximum": 180, "default": 0,
      "description": "magnetic declination, east positive: true heading = magnetic + declination"},
    "max_dt_s": {"type": "number", "x-unit": "s", "minimum": 1e-4, "maximum": 10, "default": 0.1,
      "description": "longer gaps between samples are integrated as this"},
    "mag_max_age_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "a magnetometer reading corrects the IMU samples at most this long after it"},
    "mag_field_ut": {"type": "number", "x-unit": "uT", "minimum": 0, "maximum": 1000, "default": 0,
      "description": "local field strength; 0 = learn it (median over mag_learn_s)"},
    "mag_dip_deg": {"type": "number", "x-unit": "deg", "minimum": -100, "maximum": 90, "default": -100,
      "description": "local dip (inclination), down positive; below -90 = learn it"},
    "mag_field_tolerance_ut": {"type": "number", "x-unit": "uT", "minimum": 0.01, "maximum": 1000, "default": 6,
      "description": "a reading is used only while its strength is within this of the local field"},
    "mag_dip_tolerance_deg": {"type": "number", "x-unit": "deg", "minimum": 0.01, "maximum": 180, "default": 6,
      "description": "and its dip within this of the local dip"},
    "mag_learn_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 600, "default": 3,
      "description": "window over which the local field is learnt"}
  }
})json";
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_IMU) | PN_REC_MASK(PN_REC_MAG);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_ATTITUDE);

    MadgwickAttitude(Params& p, const CreateContext&)
        : marg_(p.text("form") == "marg"),
          filter_(pednav::navmath::madgwick_config(p)),
          initial_heading_rad_(p.number("initial_heading_deg") * M_PI / 180.0),
          declination_rad_(p.number("declination_deg") * M_PI / 180.0),
          init_ns_(static_cast<int64_t>(p.number("init_s") * 1e9)),
          mag_max_age_ns_(static_cast<int64_t>(p.number("mag_max_age_s") * 1e9)),
          gate_(pednav::navmath::magnetic_field_gate_config(p, "mag_")) {}

    void on_imu(const pn_imu_t& imu) override {
        const Vec3 a(imu.accel_mps2[0], imu.accel_mps2[1], imu.accel_mps2[2]);
        const Vec3 w(imu.gyro_radps[0], imu.gyro_radps[1], imu.gyro_radps[2]);
        if (!std::isfinite(a.sum()) || !std::isfinite(w.sum())) throw InputError("non-finite IMU sample");
        const int64_t t = imu.header.t_ns;
        if (!filter_.aligned()) {
            if (!(a.squaredNorm() > 0)) return;
            filter_.align(t, a, initial_heading_rad_);
            t_start_ns_ = t;
        } else {
            if (!filter_.started()) t_start_ns_ = t;
            const bool use_mag = has_mag_ && t - mag_t_ns_ <= mag_max_age_ns_;
            if (!filter_.update(t, w, a, use_mag ? &mag_ : nullptr)) return;
            mag_used_ = use_mag;
        }
        // In the MARG form the start heading is not known until the first
        // accepted magnetometer reading (or init_s without one): no attitude
        // before, so that nothing downstream takes the provisional heading.
        if (marg_ && !heading_from_mag_ && !app_attitude_ && t - t_start_ns_ < init_ns_) return;
        auto r = make_record<pn_attitude_t>(t);
        const Quat& q = filter_.q();
        r.q_enu_from_body[0] = q.w();
        r.q_enu_from_body[1] = q.x();
        r.q_enu_from_body[2] = q.y();
        r.q_enu_from_body[3] = q.z();
        r.heading_rad = pednav::navmath::heading_of(q);
        for (int i = 0; i < 3; ++i) r.gyro_bias_radps[i] = filter_.gyro_bias()[i];
        if (mag_used_) r.header.flags = PN_ATTITUDE_FLAG_MAG_USED;
        emit(r);
    }
    void on_mag(const pn_mag_t& m) override {
        if (!marg_ || !filter_.aligned()) return;
        const Vec3 b(m.mag_ut[0], m.mag_ut[1], m.mag_ut[2]);
        if (!std::isfinite(b.sum())) throw InputError("non-finite magnetometer sample");
        const Vec3 up = filter_.up_body();
        if (!gate_.accept(m.header.t_ns, b, up)) {
            has_mag_ = false;
            return;
        }
        // The first accepted reading of the start sets the heading (unless the app gave the attitude).
        if (!heading_from_mag_ && !app_attitude_ && m.header.t_ns - t_start_ns_ <= init_ns_) {
            heading_from_mag_ = true;
            const double heading = pednav::navmath::magnetic_heading(up, b) + declination_rad_;
            filter_.set_heading(heading);
        }
        has_mag_ = true;
        mag_ = b;
        mag_t_ns_ = m.header.t_ns;
    }
    bool set_attitude(int64_t, const double q[4]) override {
        const Quat qa(q[0], q[1], q[2], q[3]);
        if (!(std::fabs(qa.norm() - 1.0) < 1e-3)) throw InputError("set_attitude: not a unit quaternion");
        filter_.set_attitude(qa);
        app_attitude_ = true;
        return true;
    }

private:
    bool marg_;
    pednav::navmath::Madgwick filter_;
    double initial_heading_rad_, declination_rad_;
    int64_t init_ns_, mag_max_age_ns_;
    pednav::navmath::MagneticFieldGate gate_;
    bool has_mag_ = false, mag_used_ = false, heading_from_mag_ = false, app_attitude_ = false;
    Vec3 mag_ = Vec3::Zero();
    int64_t mag_t_ns_ = 0, t_start_ns_ = 0;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.pdr.madgwick", "1.0.0", MadgwickAttitude)
