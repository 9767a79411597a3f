// SPDX-License-Identifier: Apache-2.0
// Waist (belt) position filter: the step/GNSS fusion EKF of pednav_pdr_fusion
// (state [E, N, speed, altitude, heading, step length], and the GNSS fixes'
// error correlated over tens of seconds) predicted per step
// with the step-length model of pednav_pdr and the attitude's heading change,
// corrected by GNSS fixes (in the engine's ENU frame, through its geodetic
// origin) and the barometer; GNSS alone, fused or steps alone by the fixes'
// quality (pednav_pdr_fusion/gnss_mode.hpp), named in every output's source.
// The output is the filter's state in every mode: with good fixes it follows
// them at their own accuracy (GNSS), with poor ones it weighs them less
// (fused), without any it runs on the steps, continuous from one to the next.
// One PN_REC_POSITION and one PN_REC_STRIDE per step; a position for each
// static step record (the walker stopped).
#include <cmath>
#include <algorithm>
#include <memory>
#include <vector>

#include <pednav_barometry/params_schema.hpp>
#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_geodesy/enu.hpp>
#include <pednav_navmath/so3.hpp>
#include <pednav_pdr/step_length_model.hpp>
#include <pednav_pdr_fusion/gnss_mode.hpp>
#include <pednav_pdr_fusion/step_gnss_ekf.hpp>
#include <pednav_sdk/library.hpp>

namespace {
using namespace pednav::sdk;
using pednav::navmath::Quat;
using pednav::navmath::Vec3;
using pednav::pdr_fusion::PositionMode;
using pednav::pdr_fusion::StepGnssEkf;

constexpr double kDeg = M_PI / 180.0;
// Ratio of step length to body height at a normal pace (the height default).
constexpr double kStepToHeight = 0.415;

class WaistFusion : public PositionFilter {
public:
    static constexpr const char* kId = "org.pednav.waist.fusion";
    static constexpr const char* kVendor = "pednav";
    static constexpr const char* const kFeatures[] = {"mount:waist", "needs:step", "needs:attitude", "uses:gnss",
                                                      "uses:baro", nullptr};
    static constexpr const char* kName = "waist step/GNSS fusion EKF";
    static constexpr const char* kVersion = "1.1.0";
    static constexpr const char* kDescription =
        "EKF [E, N, speed, altitude, heading, step length] per step (waist paper sec. 4.4, eq. 4.14-4.22 "
        "with one heading convention) and the fixes' correlated error (Gauss-Markov), step length "
        "L = k (amax - amin)^(1/b) + beta, GNSS position and velocity "
        "behind an innovation gate, barometric altitude; GNSS alone, fused or steps alone by fix quality";
    static constexpr const char* kParamsSchema = R"json({
  "type": "object", "additionalProperties": false,
  "properties": {
    "step_model_k": {"type": "number", "x-unit": "m/(m/s^2)^(1/b)", "minimum": 0, "maximum": 10, "default": 0,
      "description": "k of L = k (amax - amin)^(1/b) + beta (eq. 3.1), per user (pednav calibrate); 0 = from user_height_m"},
    "step_model_b": {"type": "number", "minimum": 0.5, "maximum": 10, "default": 4,
      "description": "the root b (Weinberg: 4)"},
    "step_model_beta_m": {"type": "number", "x-unit": "m", "minimum": -2, "maximum": 2, "default": 0,
      "description": "the offset beta (with step_model_k 0: not used, the height default has none)"},
    "user_height_m": {"type": "number", "x-unit": "m", "minimum": 0.5, "maximum": 2.5, "default": 1.7,
      "description": "for a user never calibrated: a step of step_model_typical_range_mps2 is 0.415 times this"},
    "step_model_typical_range_mps2": {"type": "number", "x-unit": "m/s^2", "minimum": 0.1, "maximum": 50, "default": 3.0,
      "description": "the waist step detector's peak-to-peak at a normal pace (mean over the ipol lower-back walks), for the height default"},
    "heading_offset_deg": {"type": "number", "x-unit": "deg", "minimum": -360, "maximum": 360, "default": 0,
      "description": "walking direction minus the sensor's heading at the start (GNSS learns it on the way)"},
    "heading_jump_rad": {"type": "number", "x-unit": "rad", "minimum": 0.01, "maximum": 3.2, "default": 0.3,
      "description": "an attitude change this large between two records is a re-reference (a new yaw source), not a turn"},
    "position_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.02,
      "description": "process noise of E, N per step (eq. 4.15 w_E, w_N)"},
    "speed_sd_mps": {"type": "number", "x-unit": "m/s", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "process noise of the speed per step (w_S)"},
    "altitude_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "process noise of the altitude per step (w_A)"},
    "heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 1, "default": 0.001,
      "description": "process noise of the walking direction per step (w_psi)"},
    "step_length_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 1, "default": 0.0005,
      "description": "process noise of the step length's offset from the model per step (w_L): how fast the model's error for this walker changes"},
    "model_speed_sd_mps": {"type": "number", "x-unit": "m/s", "minimum": 1e-6, "maximum": 10, "default": 0.1,
      "description": "sd of L times the step frequency as an observation of the speed (eq. 4.22 S_INS)"},
    "init_position_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 1000, "default": 0.1,
      "description": "P0 of E, N at the start point"},
    "init_heading_sd_rad": {"type": "number", "x-unit": "rad", "minimum": 0, "maximum": 4, "default": 0.5,
      "description": "P0 of the walking direction"},
    "init_step_length_sd_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 2, "default": 0.1,
      "description": "P0 of the step length"},
    "use_barometer": {"type": "boolean", "default": true,
      "description": "barometric altitude observes A"},
    "baro_altitude_sd_m": {"type": "number", "x-unit": "m", "minimum": 1e-6, "maximum": 100, "default": 0.3,
      "description": "sd of a barometric altitude"},
    "use_gnss": {"type": "boolean", "default": true,
      "description": "GNSS fixes correct the track (they need the engine's geodetic origin, or give it)"},
    "gnss_min_sd_m": {"type": "number", "x-unit": "m", "minimum": 0.01, "maximum": 100, "default": 0.5,
      "description": "floor of a fix's sd per axis (h_accuracy / sqrt 2)"},
    "gnss_velocity_sd_mps": {"type": "number", "x-unit": "m/s", "minimum": 0.001, "maximum": 10, "default": 0.2,
      "description": "sd of a GNSS velocity component"},
    "gnss_course_min_speed_mps": {"type": "number", "x-unit": "m/s", "minimum": 0, "maximum": 50, "default": 0.8,
      "description": "a GNSS course observes the walking direction at this speed or faster; 0 = never"},
    "gate_chi2": {"type": "number", "minimum": 0.1, "maximum": 1e6, "default": 16,
      "description": "innovation gate: a GNSS observation whose normalised innovation squared is above this is rejected (multipath)"},
    "gate_max_rejections": {"type": "integer", "minimum": 1, "maximum": 10000, "default": 10,
      "description": "this many rejected fixes in a row that agree with each other restart the track at the fix"},
    "recover_spread_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 1000, "default": 10,
      "description": "... each innovation within this of the one before"},
    "gnss_max_accuracy_m": {"type": "number", "x-unit": "m", "minimum": 0.01, "maximum": 1000, "default": 25,
      "description": "fixes less accurate (h_accuracy, 1 sigma) are not used"},
    "gnss_min_satellites": {"type": "integer", "minimum": 0, "maximum": 100, "default": 4,
      "description": "fixes of fewer satellites (when known) are not used"},
    "gnss_good_accuracy_m": {"type": "number", "x-unit": "m", "minimum": 0.01, "maximum": 1000, "default": 5,
      "description": "GNSS alone needs a fix at least this accurate ..."},
    "gnss_good_satellites": {"type": "integer", "minimum": 0, "maximum": 100, "default": 6,
      "description": "... of at least this many satellites (when known) ..."},
    "gnss_consistent_chi2": {"type": "number", "minimum": 0.01, "maximum": 1e6, "default": 9,
      "description": "... that agrees with the steps: normalised innovation squared at most this"},
    "gnss_sd_scale": {"type": "number", "minimum": 1, "maximum": 100, "default": 1,
      "description": "each fix counts with its sd (h_accuracy / sqrt 2 per axis) times this (above 1 for a receiver that reports itself better than it is)"},
    "gnss_error_time_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 3600, "default": 60,
      "description": "correlation time of the fixes' errors (atmosphere, multipath), estimated as two first-order Gauss-Markov states; 0 = each fix's error independent"},
    "gnss_white_sd_m": {"type": "number", "x-unit": "m", "minimum": 0.01, "maximum": 100, "default": 0.5,
      "description": "with gnss_error_time_s: the part of a fix's sd per axis that is independent from fix to fix (the rest is correlated)"},
    "gnss_fused_sd_scale": {"type": "number", "minimum": 1, "maximum": 100, "default": 2,
      "description": "a fix that is not good by accuracy and satellites (fused mode) counts with its sd times this"},
    "gnss_timeout_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 600, "default": 3,
      "description": "steps alone this long after the last used fix"},
    )json" PEDNAV_BAROMETER_PARAMS_SCHEMA(2.0, 0.5, 1.0, 3.4, 0.5, 2.0) R"json(
  }
})json";
    static constexpr uint64_t kConsumes = PN_REC_MASK(PN_REC_STEP) | PN_REC_MASK(PN_REC_ATTITUDE) |
                                          PN_REC_MASK(PN_REC_GNSS) | PN_REC_MASK(PN_REC_BARO);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE);

    WaistFusion(Params& p, const CreateContext&)
        : model_(read_model(p)),
          typical_range_mps2_(p.number("step_model_typical_range_mps2")),
          heading_offset_rad_(p.number("heading_offset_deg") * kDeg),
          heading_jump_rad_(p.number("heading_jump_rad")),
          use_baro_(p.boolean("use_barometer")),
          baro_sd_m_(p.number("baro_altitude_sd_m")),
          use_gnss_(p.boolean("use_gnss")),
          fused_sd_scale_(p.number("gnss_fused_sd_scale")),
          gnss_sd_scale_(p.number("gnss_sd_scale")),
          ekf_(pednav::pdr_fusion::step_gnss_ekf_config(p)),
          mode_(pednav::pdr_fusion::gnss_mode_config(p)),
          altimeter_(pednav::barometry::barometric_altimeter_config(p, "baro_")) {
        if (typical_range_mps2_ <= 0) Params::fail("step_model_typical_range_mps2", "must be > 0");
    }

    void on_attitude(const pn_attitude_t& a) override {
        const Quat q(a.q_enu_from_body[0], a.q_enu_from_body[1], a.q_enu_from_body[2], a.q_enu_from_body[3]);
        heading_rad_ = a.heading_rad;
        if (has_q_) {
            // The rotation between the two records in ENU; its vertical part
            // is the heading change (counter-clockwise positive about up).
            const Vec3 r = pednav::navmath::quat_log(pednav::navmath::quat_mul_unit(q, q_.conjugate()));
            if (r.norm() < heading_jump_rad_) yaw_rad_ -= r.z();
        }
        q_ = q;
        has_q_ = true;
        yaw_t_[yaw_n_ % kYawRing] = a.header.t_ns;
        yaw_v_[yaw_n_ % kYawRing] = yaw_rad_;
        ++yaw_n_;
    }

    void on_baro(const pn_baro_t& b) override {
        if (use_baro_) altimeter_.push(b.header.t_ns, b.pressure_pa);
    }

    void on_gnss(const pn_gnss_t& g) override {
        // Without an attitude yet there is no walking direction to start from.
        if (!use_gnss_ || !has_q_ || !mode_.usable(g.h_accuracy_m, g.satellites, g.fix_type)) return;
        pn_geo_point_t o;
        if (!origin(o)) {
            pn_geo_point_t p{g.lat_deg, g.lon_deg, g.height_m};
            offer_origin(p);
            if (!origin(o)) return;
        }
        double enu[3];
        pednav::geodesy::geodetic_to_enu({o.lat_deg, o.lon_deg, o.height_m}, g.lat_deg, g.lon_deg, g.height_m, enu);
        // Per axis; a fix that cannot be good on its own counts for less (fused).
        const double sd_m = gnss_sd_scale_ * g.h_accuracy_m / std::sqrt(2.0) *
                            (mode_.may_be_good(g.h_accuracy_m, g.satellites) ? 1.0 : fused_sd_scale_);
        const bool has_vel = (g.header.flags & PN_GNSS_FLAG_HAS_VELOCITY) != 0;
        if (!ekf_.started()) {
            // No step yet: the track starts at the fix.
            const double psi = has_vel && std::hypot(g.vel_enu_mps[0], g.vel_enu_mps[1]) >= 0.8
                                   ? std::atan2(g.vel_enu_mps[0], g.vel_enu_mps[1])
                                   : start_heading();
            start(enu[0], enu[1], start_pos_[2], psi);
        }
        const double dt_s = t_last_step_ns_ > 0 ? std::min(2.0, static_cast<double>(g.header.t_ns - t_last_step_ns_) * 1e-9)
                                                 : 0.0;
        pednav::pdr_fusion::FixResult r;
        const double t_fix_s = static_cast<double>(g.header.t_ns) * 1e-9;
        if (!ever_fixed_) {
            // The first fix places the track (its start point was a guess),
            // as uncertain as the fix: with the start point's P0 the next
            // fixes hardly moved it, and the track kept the first fix's
            // error for a minute (4.4 m against fixes 2 m off on the
            // simulated outdoor_indoor walk, seed 4).
            const auto& x = ekf_.x();
            ekf_.place_at_fix(enu[0] - x(StepGnssEkf::S) * dt_s * std::sin(x(StepGnssEkf::PSI)),
                              enu[1] - x(StepGnssEkf::S) * dt_s * std::cos(x(StepGnssEkf::PSI)), sd_m, t_fix_s);
            r.accepted = true;
            ever_fixed_ = true;
        } else {
            r = ekf_.gnss_position(enu[0], enu[1], sd_m, dt_s, t_fix_s);
        }
        if (r.recovered) recovered_ = true, ++recoveries_;
        if (r.accepted && has_vel) ekf_.gnss_velocity(g.vel_enu_mps[0], g.vel_enu_mps[1], 0.0);
        mode_.judge(g.header.t_ns, r.accepted, g.h_accuracy_m, g.satellites, r.nis);
    }

    void on_step(const pn_step_t& s) override {
        if (s.motion_mode == PN_STEP_MODE_STATIC) {
            if (!ekf_.started()) return;
            ekf_.turn(yaw_rad_ - yaw_applied_rad_);  // turned since the last step
            yaw_applied_rad_ = yaw_rad_;
            ekf_.standing();
            emit_position(s.header.t_ns);
            return;
        }
        const double lm = pednav::pdr::step_length_m(model_, s.accel_peak_to_peak_mps2);
        if (!ekf_.started()) start(start_pos_[0], start_pos_[1], start_pos_[2], start_heading());
        const double before[2] = {ekf_.x()(StepGnssEkf::E), ekf_.x()(StepGnssEkf::N)};
        const double psi_before = ekf_.x()(StepGnssEkf::PSI);
        // The heading change before the step began (a turn on the spot in a
        // pause) turns the walker where he stands; the one within the step
        // goes with it.
        const double yaw_start = yaw_at(s.t_start_ns);
        ekf_.turn(yaw_start - yaw_applied_rad_);
        ekf_.predict_step(lm, yaw_rad_ - yaw_start, s.frequency_hz);
        yaw_applied_rad_ = yaw_rad_;
        t_last_step_ns_ = s.header.t_ns;
        if (use_baro_ && altimeter_.ready()) ekf_.altitude(start_pos_[2] + altimeter_.altitude_m(), baro_sd_m_);
        const auto& x = ekf_.x();
        auto st = make_record<pn_stride_t>(s.header.t_ns);
        st.t_start_ns = s.t_start_ns;
        st.displacement_enu_m[0] = x(StepGnssEkf::E) - before[0];
        st.displacement_enu_m[1] = x(StepGnssEkf::N) - before[1];
        st.length_m = std::hypot(st.displacement_enu_m[0], st.displacement_enu_m[1]);
        st.heading_change_rad = pednav::navmath::wrap_pi(x(StepGnssEkf::PSI) - psi_before);
        const auto& P = ekf_.P();
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) st.cov_displacement_m2[3 * i + j] = 0.5 * (P(i, j) + P(j, i));
        st.stride_class = s.motion_mode == PN_STEP_MODE_UPSTAIRS     ? PN_STRIDE_CLASS_STAIRS_UP
                          : s.motion_mode == PN_STEP_MODE_DOWNSTAIRS ? PN_STRIDE_CLASS_STAIRS_DOWN
                                                                     : PN_STRIDE_CLASS_LEVEL;
        st.index = stride_index_++;
        emit_position(s.header.t_ns);
        emit(st);
    }

    bool set_start(const double pos[3], double heading_rad) override {
        for (int i = 0; i < 3; ++i) start_pos_[i] = pos[i];
        if (std::isfinite(heading_rad)) start_heading_rad_ = heading_rad, has_start_heading_ = true;
        return true;
    }

private:
    static pednav::pdr::StepLengthModel read_model(Params& p) {
        const double k = p.number("step_model_k"), b = p.number("step_model_b"), beta = p.number("step_model_beta_m");
        const double height = p.number("user_height_m"), typical = p.number("step_model_typical_range_mps2");
        if (k > 0) return {k, b, beta};
        return pednav::pdr::step_length_model_for_height(height, kStepToHeight, typical, b);
    }
    double start_heading() const {
        return has_start_heading_ ? start_heading_rad_ : heading_rad_ + heading_offset_rad_;
    }
    void start(double e, double n, double a, double psi) {
        ekf_.start(e, n, a, psi, pednav::pdr::step_length_m(model_, typical_range_mps2_));
        yaw_applied_rad_ = yaw_rad_;
    }
    // The attitude's accumulated heading at t: the newest record at or before
    // it (the oldest kept when all are later).
    double yaw_at(int64_t t_ns) const {
        const uint64_t kept = std::min<uint64_t>(yaw_n_, kYawRing);
        for (uint64_t i = 0; i < kept; ++i) {
            const uint64_t k = (yaw_n_ - 1 - i) % kYawRing;
            if (yaw_t_[k] <= t_ns || i + 1 == kept) return yaw_v_[k];
        }
        return yaw_rad_;
    }

    void emit_position(int64_t t_ns) {
        const auto& x = ekf_.x();
        const auto& P = ekf_.P();
        auto p = make_record<pn_position_t>(t_ns);
        const PositionMode m = mode_.mode(t_ns);
        p.pos_enu_m[0] = x(StepGnssEkf::E);
        p.pos_enu_m[1] = x(StepGnssEkf::N);
        p.pos_enu_m[2] = x(StepGnssEkf::A);
        p.source = m == PositionMode::gnss    ? PN_POSITION_SOURCE_GNSS
                   : m == PositionMode::fused ? PN_POSITION_SOURCE_FUSED
                                              : PN_POSITION_SOURCE_INERTIAL;
        const double psi = x(StepGnssEkf::PSI), v = x(StepGnssEkf::S);
        p.vel_enu_mps[0] = v * std::sin(psi);
        p.vel_enu_mps[1] = v * std::cos(psi);
        p.heading_rad = psi;
        const int idx[3] = {StepGnssEkf::E, StepGnssEkf::N, StepGnssEkf::A};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) p.cov_enu_m2[3 * i + j] = 0.5 * (P(idx[i], idx[j]) + P(idx[j], idx[i]));
        p.header.flags = PN_POSITION_FLAG_HAS_VELOCITY;
        if (use_baro_ && altimeter_.ready()) {
            p.floor = altimeter_.floor();
            p.header.flags |= PN_POSITION_FLAG_HAS_FLOOR;
        }
        if (recovered_) p.header.flags |= PN_POSITION_FLAG_RECOVERED;
        recovered_ = false;
        p.recoveries = recoveries_;
        emit(p);
    }

    pednav::pdr::StepLengthModel model_;
    double typical_range_mps2_, heading_offset_rad_, heading_jump_rad_;
    bool use_baro_;
    double baro_sd_m_;
    bool use_gnss_;
    double fused_sd_scale_, gnss_sd_scale_;
    StepGnssEkf ekf_;
    pednav::pdr_fusion::GnssMode mode_;
    pednav::barometry::BarometricAltimeter altimeter_;

    Quat q_ = Quat::Identity();
    bool has_q_ = false;
    double heading_rad_ = 0;
    // The attitude's heading accumulated from its rotations about the
    // vertical (clockwise), what of it the filter has applied, and a ring of
    // its recent values by time (4096 records: 20 s at 200 Hz, longer than
    // any step).
    static constexpr uint64_t kYawRing = 4096;
    double yaw_rad_ = 0, yaw_applied_rad_ = 0;
    std::vector<int64_t> yaw_t_ = std::vector<int64_t>(kYawRing);
    std::vector<double> yaw_v_ = std::vector<double>(kYawRing);
    uint64_t yaw_n_ = 0;
    double start_pos_[3] = {0, 0, 0};
    double start_heading_rad_ = 0;
    bool has_start_heading_ = false;
    bool ever_fixed_ = false, recovered_ = false;
    uint32_t recoveries_ = 0;
    int64_t t_last_step_ns_ = 0;
    int32_t stride_index_ = 0;
};

}  // namespace

PEDNAV_PLUGIN_LIBRARY("org.pednav.waist.fusion", "1.1.0", WaistFusion)
