// SPDX-License-Identifier: Apache-2.0
// What the two step position filters share: the IMU sample, its attitude and
// the step that ends at it, joined by time; the walking heading; the step
// vector (pdr::StepVectorBuffer: the double integral of the world-frame
// horizontal acceleration over each step); height and floor from the
// barometer; one STRIDE per walking step and one POSITION per step (pauses
// included) and per floor change. The derived class gives the displacement.
//
// Walking heading of a step: the circular mean over the step of the heading
// of the body axis forward_axis ("auto": the most level body axis at the
// start), plus an offset between that axis and the walking direction. The
// offset is heading_offset_deg, or, with learn_offset_steps > 0, learnt: the
// exponentially weighted circular mean over that many steps of the step
// vector's direction (backwards, eq. (1)) minus the axis heading, over
// straight steps of steady walking (from the third step of a bout on),
// starting from heading_offset_deg as if learnt over that many steps (with
// auto, from the first learnt step). When the app gives the start heading H, the
// walking heading is H plus the axis heading's change since the start, and
// the offset does not enter.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <pednav_barometry/params_schema.hpp>
#include <pednav_barometry/barometric_altimeter.hpp>
#include <pednav_navmath/angles.hpp>
#include <pednav_pdr/step_vector.hpp>
#include <pednav_pdr/walking_heading.hpp>
#include <pednav_sdk/library.hpp>
#include <pednav_sdk/time_join.hpp>

namespace pednav::plugins {

using namespace pednav::sdk;

// The parameters both filters declare: schema properties, joined into each
// filter's schema at compile time (join_schema).
inline constexpr char kCommonParams[] = R"json(
    "forward_axis": {"type": "string", "enum": ["x", "-x", "y", "-y", "z", "-z", "auto"], "default": "auto",
      "description": "the body axis that points the way the walker faces (x for the engine's forward-left-up body frame); auto: the most level body axis at the start, its direction learnt (needs learn_offset_steps)"},
    "heading_offset_deg": {"type": "number", "x-unit": "deg", "minimum": -180, "maximum": 180, "default": 0,
      "description": "walking direction minus the heading of forward_axis (a phone held turned); the start of the learnt offset; unused when the app gives the start heading"},
    "learn_offset_steps": {"type": "number", "minimum": 0, "maximum": 1000, "default": 20,
      "description": "learn the offset from the step vectors' directions over about this many steps (a sensor that does not point the way the walker goes); 0 = heading_offset_deg as given"},
    "max_step_s": {"type": "number", "x-unit": "s", "minimum": 0.1, "maximum": 10, "default": 1.5,
      "description": "the step vector holds the samples of a step at most this long before its end"},
    "length_sd_fraction": {"type": "number", "minimum": 0, "maximum": 1, "default": 0.1,
      "description": "standard deviation of a step's length, as a fraction of it (the stride covariance)"},
    "heading_sd_deg": {"type": "number", "x-unit": "deg", "minimum": 0, "maximum": 90, "default": 3,
      "description": "standard deviation of a step's direction (the stride covariance)"},
    )json" PEDNAV_BAROMETER_PARAMS_SCHEMA(5, 0.3, 1.0, 3.5, 0.1, 5) R"json()json";

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

    // uses_step_vector: the derived filter needs each step's double integral.
    StepFilterBase(Params& p, bool uses_step_vector)
        : auto_axis_(p.text("forward_axis") == "auto"),
          axis_(auto_axis_ ? pednav::pdr::BodyAxis{} : pednav::pdr::parse_body_axis(p.text("forward_axis"))),
          heading_offset_rad_(p.number("heading_offset_deg") * M_PI / 180.0),
          learn_steps_(p.number("learn_offset_steps")),
          length_sd_fraction_(p.number("length_sd_fraction")),
          heading_sd_rad_(p.number("heading_sd_deg") * M_PI / 180.0),
          buffer_(p.number("max_step_s")),
          altimeter_(pednav::barometry::barometric_altimeter_config(p, "baro_")),
          offset_sin_(std::sin(heading_offset_rad_)),
          offset_cos_(std::cos(heading_offset_rad_)) {
        if (auto_axis_ && learn_steps_ <= 0)
            Params::fail("forward_axis", "is auto, which needs learn_offset_steps > 0 (the axis's direction is learnt)");
        uses_step_vector_ = uses_step_vector || learn_steps_ > 0;
    }

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
    // The displacement (east, north) of a walking step; false for none.
    // heading: the walking heading; vector: the step's double integral of the
    // horizontal acceleration in the attitude's frame (zero unless the filter
    // uses the step vector); yaw_align: the clockwise turn from the
    // attitude's frame to the start-aligned one.
    virtual bool step_displacement(const pn_step_t& step, double heading_rad, const pednav::pdr::PlaneVector& vector,
                                   double yaw_align_rad, double& east_m, double& north_m) = 0;
    // remove_mean of the double integral (the step vector's choice).
    virtual bool remove_mean_accel() const { return false; }

private:
    void process(const Join::Sample& s) {
        if (const pn_attitude_t* att = s.get<pn_attitude_t>()) {
            const pn_attitude_t& a = *att;
            if (!started_) start(a);
            const double h = pednav::pdr::axis_heading_rad(a.q_enu_from_body, axis_);
            if (std::isfinite(h)) sum_sin_ += std::sin(h), sum_cos_ += std::cos(h);
            const pn_imu_t* imu = s.get<pn_imu_t>();
            if (uses_step_vector_ && imu) {
                const double w = a.q_enu_from_body[0], x = a.q_enu_from_body[1], y = a.q_enu_from_body[2],
                             z = a.q_enu_from_body[3];
                const double* f = imu->accel_mps2;
                // The first two rows of R(q) times the specific force: gravity has no horizontal part.
                const double e = (1 - 2 * (y * y + z * z)) * f[0] + 2 * (x * y - w * z) * f[1] + 2 * (x * z + w * y) * f[2];
                const double n = 2 * (x * y + w * z) * f[0] + (1 - 2 * (x * x + z * z)) * f[1] + 2 * (y * z - w * x) * f[2];
                buffer_.add({a.header.t_ns, e, n});
            }
        }
        if (const pn_step_t* step = s.get<pn_step_t>()) close_step(*step);
    }
    // The first attitude: the forward axis (auto: the most level one) and its heading now.
    void start(const pn_attitude_t& a) {
        started_ = true;
        if (auto_axis_) {
            const double w = a.q_enu_from_body[0], x = a.q_enu_from_body[1], y = a.q_enu_from_body[2],
                         z = a.q_enu_from_body[3];
            const double up[3] = {std::fabs(2 * (x * z - w * y)), std::fabs(2 * (y * z + w * x)),
                                  std::fabs(1 - 2 * (x * x + y * y))};
            axis_.index = up[0] <= up[1] && up[0] <= up[2] ? 0 : (up[1] <= up[2] ? 1 : 2);
            axis_.sign = 1.0;
        }
        start_axis_heading_rad_ = pednav::pdr::axis_heading_rad(a.q_enu_from_body, axis_);
    }
    double offset_rad() const { return std::atan2(offset_sin_, offset_cos_); }
    void close_step(const pn_step_t& step) {
        // The axis heading over the step: the circular mean of its samples.
        if (sum_sin_ != 0 || sum_cos_ != 0) axis_heading_rad_ = std::atan2(sum_sin_, sum_cos_);
        sum_sin_ = sum_cos_ = 0;
        const bool walking = step.motion_mode != PN_STEP_MODE_STATIC;
        pednav::pdr::PlaneVector v;
        if (uses_step_vector_ && walking) v = buffer_.close(step.t_start_ns, step.header.t_ns, remove_mean_accel());
        walking_run_ = walking ? walking_run_ + 1 : 0;
        // Learnt from steady straight walking only: the first steps of a bout
        // accelerate (their double integral points forwards), a turn adds the
        // centripetal acceleration.
        if (learn_steps_ > 0 && step.motion_mode == PN_STEP_MODE_STRAIGHT && walking_run_ > 2 &&
            std::isfinite(axis_heading_rad_) && (v.east_m != 0 || v.north_m != 0)) {
            // The walker goes against the step vector (eq. 1: K < 0).
            const double d = std::atan2(-v.east_m, -v.north_m) - axis_heading_rad_;
            // A running mean over the first steps (after the prior's weight:
            // none for auto), then exponential over learn_offset_steps.
            ++learnt_steps_;
            const double a = 1.0 / std::min(learnt_steps_ + (auto_axis_ ? 0.0 : learn_steps_), learn_steps_);
            offset_sin_ += a * (std::sin(d) - offset_sin_);
            offset_cos_ += a * (std::cos(d) - offset_cos_);
        }
        double heading = NAN;
        const bool given = std::isfinite(start_heading_rad_) && std::isfinite(start_axis_heading_rad_);
        if (std::isfinite(axis_heading_rad_))
            heading = pednav::navmath::wrap_pi(given ? start_heading_rad_ + (axis_heading_rad_ - start_axis_heading_rad_)
                                                     : axis_heading_rad_ + offset_rad());
        // The attitude's frame turned so that the walking direction at the start is the app's
        // heading: the axis heading then plus the offset (as learnt so far) is that heading.
        const double yaw_align = given ? start_heading_rad_ - start_axis_heading_rad_ - offset_rad() : 0.0;
        double de = 0, dn = 0;
        const bool moved = walking && std::isfinite(heading) && step_displacement(step, heading, v, yaw_align, de, dn);
        if (moved) emit_stride(step, de, dn);
        if (step.header.t_ns >= t_out_ns_) emit_position(step.header.t_ns, std::isfinite(heading) ? heading : last_heading_out_rad_);
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
    void emit_stride(const pn_step_t& step, double de, double dn) {
        const double length = std::hypot(de, dn);
        if (!std::isfinite(length)) throw NumericError("step displacement is not finite");
        if (altimeter_.ready()) pos_[2] = start_[2] + altimeter_.altitude_m();
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
        r.heading_change_rad = std::isfinite(prev_dir_rad_) ? pednav::navmath::wrap_pi(dir - prev_dir_rad_) : 0.0;
        prev_dir_rad_ = dir;
        r.cov_displacement_m2[0] = cee, r.cov_displacement_m2[1] = cen;
        r.cov_displacement_m2[3] = cen, r.cov_displacement_m2[4] = cnn;
        r.stride_class = step.motion_mode == PN_STEP_MODE_UPSTAIRS     ? PN_STRIDE_CLASS_STAIRS_UP
                         : step.motion_mode == PN_STEP_MODE_DOWNSTAIRS ? PN_STRIDE_CLASS_STAIRS_DOWN
                                                                       : PN_STRIDE_CLASS_LEVEL;
        r.index = stride_index_++;
        emit(r);
    }

    bool auto_axis_;
    pednav::pdr::BodyAxis axis_;
    double heading_offset_rad_, learn_steps_, length_sd_fraction_, heading_sd_rad_;
    bool uses_step_vector_ = false;
    pednav::pdr::StepVectorBuffer buffer_;
    pednav::barometry::BarometricAltimeter altimeter_;
    Join join_;
    double start_[3] = {0, 0, 0}, pos_[3] = {0, 0, 0}, cov_[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    bool started_ = false, has_baro_ = false;
    double start_heading_rad_ = NAN, start_axis_heading_rad_ = NAN;
    double offset_sin_, offset_cos_, learnt_steps_ = 0;
    double sum_sin_ = 0, sum_cos_ = 0, axis_heading_rad_ = NAN, prev_dir_rad_ = NAN, last_stride_z_ = 0;
    int32_t floor_out_ = 0, stride_index_ = 0, walking_run_ = 0;
    int64_t t_out_ns_ = INT64_MIN;
    double last_heading_out_rad_ = 0.0;
};

}  // namespace pednav::plugins
