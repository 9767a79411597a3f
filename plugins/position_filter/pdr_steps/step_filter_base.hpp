// SPDX-License-Identifier: Apache-2.0
// What the two step position filters share: the IMU sample, its attitude and
// the step that ends at it, joined by time; the walking heading (a body axis
// of the attitude, a fixed offset, and the start heading the app gives);
// height and floor from the barometer; one STRIDE per walking step and one
// POSITION per step (pauses included). The derived class gives the
// displacement of each step.
#pragma once

#include <cmath>
#include <string>

#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_navmath/angles.hpp>
#include <pednav_pdr/walking_heading.hpp>
#include <pednav_sdk/library.hpp>
#include <pednav_sdk/time_join.hpp>

namespace pednav::plugins {

using namespace pednav::sdk;

// The parameters both filters declare: schema properties, joined into each
// filter's schema at compile time (join_schema).
inline constexpr char kCommonParams[] = R"json(
    "forward_axis": {"type": "string", "enum": ["x", "-x", "y", "-y", "z", "-z"], "default": "x",
      "description": "the body axis that points the way the walker faces (x for the engine's forward-left-up body frame)"},
    "heading_offset_deg": {"type": "number", "x-unit": "deg", "minimum": -180, "maximum": 180, "default": 0,
      "description": "walking direction minus the heading of forward_axis (a phone held turned); unused when the app gives the start heading, which fixes it"},
    "length_sd_fraction": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.1,
      "description": "standard deviation of a step's length, as a fraction of it (the stride covariance)"},
    "heading_sd_deg": {"type": "number", "x-unit": "deg", "minimum": 0, "maximum": 90, "default": 3,
      "description": "standard deviation of a step's direction (the stride covariance)"},
    "baro_reference_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 600, "default": 5,
      "description": "barometer: the reference pressure (altitude 0, floor 0) is the mean over the first this long"},
    "baro_smoothing_s": {"type": "number", "x-unit": "s", "minimum": 0, "maximum": 60, "default": 0.3,
      "description": "barometer: time constant of the altitude low-pass"},
    "baro_rate_smoothing_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 60, "default": 1.0,
      "description": "barometer: time constant of the vertical rate's low-pass"},
    "baro_floor_height_m": {"type": "number", "x-unit": "m", "minimum": 0.5, "maximum": 20, "default": 3.5,
      "description": "barometer: height of one floor"},
    "baro_floor_hysteresis_m": {"type": "number", "x-unit": "m", "minimum": 0, "maximum": 10, "default": 0.1,
      "description": "barometer: beyond half a floor by this much before the floor changes"},
    "baro_max_gap_s": {"type": "number", "x-unit": "s", "minimum": 0.01, "maximum": 600, "default": 5,
      "description": "barometer: a longer gap between readings restarts its filters"})json";

// A schema text: head, the common properties, tail; a constant.
template <size_t A, size_t B, size_t C>
struct JoinedSchema {
    char text[A + B + C - 2] = {};
    constexpr JoinedSchema(const char (&a)[A], const char (&b)[B], const char (&c)[C]) {
        size_t k = 0;
        for (size_t i = 0; i + 1 < A; ++i) text[k++] = a[i];
        for (size_t i = 0; i + 1 < B; ++i) text[k++] = b[i];
        for (size_t i = 0; i < C; ++i) text[k++] = c[i];
    }
};
template <size_t A, size_t C>
constexpr auto join_schema(const char (&head)[A], const char (&tail)[C]) {
    return JoinedSchema<A, sizeof kCommonParams, C>(head, kCommonParams, tail);
}

class StepFilterBase : public PositionFilter {
protected:
    using Join = TimeJoin<pn_imu_t, pn_attitude_t, pn_step_t>;
    auto sample() {
        return [this](const Join::Sample& s) { process(s); };
    }

public:
    static constexpr uint64_t kConsumes = Join::kRecordMask | PN_REC_MASK(PN_REC_BARO);
    static constexpr uint64_t kProduces = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE);

    explicit StepFilterBase(Params& p)
        : axis_(axis(p)),
          heading_offset_rad_(p.number("heading_offset_deg") * M_PI / 180.0),
          length_sd_fraction_(p.number("length_sd_fraction")),
          heading_sd_rad_(p.number("heading_sd_deg") * M_PI / 180.0),
          altimeter_(pednav::barometry::barometric_altimeter_config(p, "baro_")) {}

    void on_imu(const pn_imu_t& r) override { join_.add(r, sample()); }
    void on_attitude(const pn_attitude_t& r) override { join_.add(r, sample()); }
    void on_step(const pn_step_t& r) override { join_.add(r, sample()); }
    void on_baro(const pn_baro_t& b) override {
        altimeter_.push(b.header.t_ns, b.pressure_pa);
        has_baro_ = true;
        // A floor change between steps is a position of its own (at the last
        // step's place), so the floor is not late by up to a step.
        if (altimeter_.ready() && altimeter_.floor() != floor_out_ && b.header.t_ns > t_out_ns_)
            emit_position(b.header.t_ns, last_heading_out_rad_);
    }
    void on_flush() override { join_.flush(sample()); }
    bool set_start(const double pos[3], double heading_rad) override {
        for (int i = 0; i < 3; ++i) pos_[i] = start_[i] = pos[i];
        last_stride_z_ = pos[2];
        start_heading_rad_ = heading_rad;
        return true;
    }

protected:
    // A sample with its attitude (IMU may be absent); the walking heading of it.
    virtual void on_attitude_sample(const pn_imu_t* imu, const pn_attitude_t& att, double walking_heading_rad) = 0;
    // The displacement (east, north) of a walking step; false for none.
    virtual bool step_displacement(const pn_step_t& step, double walking_heading_rad, double& east_m,
                                   double& north_m) = 0;

    // The walking heading of an attitude (rad, clockwise from north), NaN when
    // the forward axis is vertical.
    double walking_heading(const pn_attitude_t& att) {
        const double h = pednav::pdr::axis_heading_rad(att.q_enu_from_body, axis_);
        if (std::isnan(h)) return NAN;
        if (!aligned_) {
            // The app's start heading is the walking direction now: it fixes the offset.
            aligned_ = true;
            yaw_align_rad_ = std::isfinite(start_heading_rad_) ? start_heading_rad_ - h - heading_offset_rad_ : 0.0;
        }
        return pednav::navmath::wrap_pi(h + heading_offset_rad_ + yaw_align_rad_);
    }
    // The rotation from the attitude's ENU to the start-aligned ENU, rad
    // (clockwise), 0 until the first attitude.
    double yaw_align_rad() const { return yaw_align_rad_; }

private:
    static pednav::pdr::BodyAxis axis(Params& p) { return pednav::pdr::parse_body_axis(p.text("forward_axis")); }

    void process(const Join::Sample& s) {
        const pn_attitude_t* att = s.get<pn_attitude_t>();
        if (att) {
            const double h = walking_heading(*att);
            if (std::isfinite(h)) {
                sum_sin_ += std::sin(h), sum_cos_ += std::cos(h);
                last_heading_rad_ = h;
            }
            on_attitude_sample(s.get<pn_imu_t>(), *att, h);
        }
        if (const pn_step_t* step = s.get<pn_step_t>()) close_step(*step);
    }
    // The step's walking heading: the circular mean over its samples.
    void close_step(const pn_step_t& step) {
        const double heading = (sum_sin_ != 0 || sum_cos_ != 0) ? std::atan2(sum_sin_, sum_cos_) : last_heading_rad_;
        sum_sin_ = sum_cos_ = 0;
        double de = 0, dn = 0;
        const bool moved = step.motion_mode != PN_STEP_MODE_STATIC && std::isfinite(heading) &&
                           step_displacement(step, heading, de, dn);
        if (altimeter_.ready()) pos_[2] = start_[2] + altimeter_.altitude_m();
        if (moved) emit_stride(step, heading, de, dn);
        if (step.header.t_ns >= t_out_ns_) emit_position(step.header.t_ns, std::isfinite(heading) ? heading : 0.0);
    }
    void emit_position(int64_t t_ns, double heading_rad) {
        if (altimeter_.ready()) pos_[2] = start_[2] + altimeter_.altitude_m();
        auto r = make_record<pn_position_t>(t_ns);
        for (int i = 0; i < 3; ++i) r.pos_enu_m[i] = pos_[i];
        for (int i = 0; i < 9; ++i) r.cov_enu_m2[i] = cov_[i];
        r.heading_rad = heading_rad;
        r.source = PN_POSITION_SOURCE_INERTIAL;
        // With a barometer the floor is known from the start: floor 0 while
        // the altimeter learns its reference there.
        if (has_baro_) {
            r.header.flags |= PN_POSITION_FLAG_HAS_FLOOR;
            r.floor = floor_out_ = altimeter_.ready() ? altimeter_.floor() : 0;
        }
        t_out_ns_ = t_ns;
        last_heading_out_rad_ = heading_rad;
        emit(r);
    }
    void emit_stride(const pn_step_t& step, double heading, double de, double dn) {
        const double length = std::hypot(de, dn);
        if (!std::isfinite(length)) throw NumericError("step displacement is not finite");
        const double dz = pos_[2] - last_stride_z_;
        pos_[0] += de, pos_[1] += dn;
        last_stride_z_ = pos_[2];
        // Covariance of the displacement from the length and direction sd:
        // J diag(sL^2, sh^2) J^T with d = L (sin h, cos h).
        const double dir = std::atan2(de, dn);
        const double sl = length_sd_fraction_ * length, sh = heading_sd_rad_ * length;
        const double s = std::sin(dir), c = std::cos(dir);
        const double cee = sl * sl * s * s + sh * sh * c * c, cnn = sl * sl * c * c + sh * sh * s * s,
                     cen = (sl * sl - sh * sh) * s * c;
        cov_[0] += cee, cov_[1] += cen, cov_[3] += cen, cov_[4] += cnn;
        auto r = make_record<pn_stride_t>(step.header.t_ns);
        r.t_start_ns = step.t_start_ns;
        r.displacement_enu_m[0] = de;
        r.displacement_enu_m[1] = dn;
        r.displacement_enu_m[2] = dz;
        r.length_m = length;
        r.heading_change_rad = std::isfinite(prev_heading_rad_) ? pednav::navmath::wrap_pi(heading - prev_heading_rad_) : 0.0;
        prev_heading_rad_ = heading;
        r.cov_displacement_m2[0] = cee, r.cov_displacement_m2[1] = cen;
        r.cov_displacement_m2[3] = cen, r.cov_displacement_m2[4] = cnn;
        r.stride_class = step.motion_mode == PN_STEP_MODE_UPSTAIRS     ? PN_STRIDE_CLASS_STAIRS_UP
                         : step.motion_mode == PN_STEP_MODE_DOWNSTAIRS ? PN_STRIDE_CLASS_STAIRS_DOWN
                                                                       : PN_STRIDE_CLASS_LEVEL;
        r.index = stride_index_++;
        emit(r);
    }

    pednav::pdr::BodyAxis axis_;
    double heading_offset_rad_, length_sd_fraction_, heading_sd_rad_;
    pednav::barometry::BarometricAltimeter altimeter_;
    Join join_;
    double start_[3] = {0, 0, 0}, pos_[3] = {0, 0, 0}, cov_[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    double start_heading_rad_ = NAN, yaw_align_rad_ = 0.0;
    bool aligned_ = false, has_baro_ = false;
    int32_t floor_out_ = 0;
    int64_t t_out_ns_ = INT64_MIN;
    double last_heading_out_rad_ = 0.0;
    double sum_sin_ = 0, sum_cos_ = 0, last_heading_rad_ = NAN, prev_heading_rad_ = NAN, last_stride_z_ = 0;
    int32_t stride_index_ = 0;
};

}  // namespace pednav::plugins
