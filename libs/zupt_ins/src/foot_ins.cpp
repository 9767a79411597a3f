// SPDX-License-Identifier: Apache-2.0
#include "pednav_zupt_ins/foot_ins.hpp"

#include <algorithm>

#include <pednav/pn_types.h>
#include <pednav_navmath/angles.hpp>
#include <pednav_navmath/heading.hpp>

namespace pednav::zupt_ins {

using navmath::heading_of;
using navmath::quat_exp;
using navmath::quat_log;
using navmath::renormalize;
using navmath::rotate;
using navmath::wrap_pi;

template <class Filter>
FootInsT<Filter>::FootInsT(const FootInsConfig& c)
    : cfg_(c), heel_strike_rad_(c.heel_strike_deg * M_PI / 180.0), levels_(c.level_match_m) {
    // |toe-up| <= the rotation angle from the anchor attitude, 2 acos|w| of
    // the relative quaternion: below the threshold (with a margin far above
    // round-off) the swing sample cannot mark a heel strike.
    skip_cos_half_ = heel_strike_rad_ > 1e-6 ? std::cos(0.5 * (heel_strike_rad_ - 1e-9)) + 1e-12 : 2.0;
    noise_.gyro_psd = c.gyro_noise_radps_per_sqrthz * c.gyro_noise_radps_per_sqrthz;
    noise_.accel_psd = c.accel_noise_mps2_per_sqrthz * c.accel_noise_mps2_per_sqrthz;
    noise_.gyro_bias_psd = c.gyro_bias_walk_radps_per_sqrts * c.gyro_bias_walk_radps_per_sqrts;
    noise_.accel_bias_psd = c.accel_bias_walk_mps2_per_sqrts * c.accel_bias_walk_mps2_per_sqrts;
    double d[Ekf15::N] = {0};
    const auto sq = [](double x) { return x * x; };
    d[Ekf15::ATT] = d[Ekf15::ATT + 1] = sq(c.init_roll_pitch_sd_rad);
    d[Ekf15::ATT + 2] = sq(c.init_heading_sd_rad);
    for (int i = 0; i < 3; ++i) {
        d[Ekf15::BG + i] = sq(c.init_gyro_bias_sd_radps);
        d[Ekf15::VEL + i] = sq(c.init_velocity_sd_mps);
        d[Ekf15::BA + i] = sq(c.init_accel_bias_sd_mps2);
    }
    ekf_.reset_covariance(d);
    ekf_.set_joseph(c.joseph_form);
    g_learning_ = !(c.gravity_mps2 > 0);
    if (!g_learning_) g_ = c.gravity_mps2;
}

template <class Filter>
void FootInsT<Filter>::set_start(const Vec3& pos, double heading_rad) {
    start_pos_ = pos;
    start_heading_ = heading_rad;
}

template <class Filter>
void FootInsT<Filter>::step(int64_t t_ns, const Vec3& a, const Vec3& w, const Quat& q_in, const Vec3& bg, bool stance,
                   SampleOut& out) {
    Quat q = q_in;
    out.correction = false;
    out.stride = false;
    out.rot_enu_rad.setZero();
    out.gyro_bias_delta.setZero();
    double dt = 0.0;

    if (!started_) {
        started_ = true;
        p_ = start_pos_;
        v_.setZero();
        h_ref_ = p_.z();
        if (std::isfinite(start_heading_)) {
            // The start heading given to the engine reaches the attitude
            // estimator as a yaw correction about ENU up.
            const Vec3 rot(0.0, 0.0, wrap_pi(heading_of(q) - start_heading_));
            q = quat_exp(rot) * q;
            out.correction = true;
            out.rot_enu_rad = rot;
        }
    } else {
        dt = std::min(std::max((t_ns - t_prev_) * 1e-9, 0.0), cfg_.max_dt_s);
    }

    if (g_learning_) {
        if (stance) {
            g_sum_ += (accel_scale_ * a - ba_).norm() / accel_scale_;
            g_n_ += 1;
            const double g_read = g_sum_ / g_n_;  // mean |a - ba| as read
            const bool rescale = cfg_.accel_rescale_above < 1.0 && g_read > 0.0 && std::isfinite(g_read) &&
                                 std::abs(g_read / cfg_.local_gravity_mps2 - 1.0) > cfg_.accel_rescale_above;
            if (rescale) {
                accel_scale_ = cfg_.local_gravity_mps2 / g_read;
                g_ = cfg_.local_gravity_mps2;
            } else {
                accel_scale_ = 1.0;
                g_ = g_read;
            }
        } else if (g_n_ > 0) {
            g_learning_ = false;
        }
    }

    const Vec3 a_scaled = accel_scale_ * a;  // exact when the scale is 1
    Mat3 R = q.toRotationMatrix();
    Vec3 f = rotate(q, a_scaled - ba_);
    if (dt > 0) {
        // Mid-interval specific force: foot-imu-zupt-zaru-ekf eq. (10)-(11)
        // with trapezoidal integration.
        const Vec3 acc = 0.5 * (f_prev_ + f) - Vec3(0.0, 0.0, g_);
        const Vec3 v_new = v_ + acc * dt;
        p_ += 0.5 * (v_ + v_new) * dt;
        v_ = v_new;
        filter_dt_acc_ += dt;
        filter_f_acc_ += f * dt;
    }
    // Covariance propagation over the time since the last filter step, with the
    // mean specific force of that time (eq. (32)); then the updates.
    const bool filter_step =
        filter_dt_acc_ > 0 && (cfg_.filter_rate_hz <= 0 || filter_dt_acc_ * cfg_.filter_rate_hz >= 0.999);
    if (filter_step) {
        const Vec3 f_mean = filter_f_acc_ / filter_dt_acc_;
        if (stance || !(cfg_.swing_propagation_s > 0)) {
            ekf_.propagate(filter_dt_acc_, R, f_mean, noise_);
        } else {
            // No measurement before the next stance: the swing's transitions
            // are multiplied together and applied every swing_propagation_s
            // (and by the next propagate or update).
            ekf_.defer_propagation(filter_dt_acc_, R, f_mean, noise_);
            if (ekf_.deferred_s() >= 0.999 * cfg_.swing_propagation_s) ekf_.apply_deferred();
        }
        filter_dt_acc_ = 0.0;
        filter_f_acc_.setZero();
    }

    if (stance && !in_stance_) begin_stance(t_ns);
    if (stance && (filter_step || dt == 0.0) && (cfg_.zupt || cfg_.zaru || cfg_.hupt)) {
        const Vec3 w_est = w - bg;
        const double rate = w_est.norm();
        if (cfg_.zupt) {
            // A stance foot rolls about its contact point on the ground. The
            // sensor sits sensor_height_m above it, so it moves horizontally
            // at w x (h up) = h (w_n, -w_e, 0) in ENU (forward, for the heel
            // and the toe rocker alike); the part of the lever along the
            // foot (vertical velocity, its sign depends on which end the foot
            // rolls on) is left to the noise, which grows with the rate.
            // The measurement's small dependence on the attitude and gyro
            // bias errors (h |w| times them) is neglected: H selects velocity.
            // Below zaru_max_radps the ZARU takes the same rate for gyro bias;
            // the rolling velocity there is at most h zaru_max_radps (5 mm/s
            // with the preset), under zupt_sd_mps.
            const double sd = cfg_.zupt_sd_mps + cfg_.zupt_lever_m * rate;
            const Vec3 w_enu = R * w_est;
            const double h = cfg_.sensor_height_m;
            const double z[3] = {h * w_enu.y() - v_.x(), -h * w_enu.x() - v_.y(), -v_.z()};
            const double var[3] = {sd * sd, sd * sd, sd * sd};
            ekf_.update_block3(Ekf15::VEL, z, var);
        }
        if (cfg_.zaru && rate < cfg_.zaru_max_radps) {
            const double var1 = cfg_.zaru_sd_radps * cfg_.zaru_sd_radps;
            const double z[3] = {w_est.x(), w_est.y(), w_est.z()};
            const double var[3] = {var1, var1, var1};
            // With zaru_moves_position false the position keeps its estimate:
            // the rotation ZARU reads as bias may be the foot's own (a
            // standing foot that sways), and the chain of correlations from
            // bias to position then moves a standing foot by metres.
            constexpr uint32_t kPosition = 7u << Ekf15::POS;
            ekf_.update_block3(Ekf15::BG, z, var, cfg_.zaru_moves_position ? 0u : kPosition);
        }
        if (cfg_.hupt && level_step_) {
            ekf_.update_scalar(Ekf15::POS + 2, h_ref_ - p_.z(), cfg_.hupt_sd_m * cfg_.hupt_sd_m);
        }
        // Inject and reset (foot-imu-zupt-zaru-ekf eq. (12)-(14)).
        const double* x = ekf_.x();
        const Vec3 phi(x[0], x[1], x[2]);
        const Vec3 dbg(x[3], x[4], x[5]);
        p_ += Vec3(x[6], x[7], x[8]);
        v_ += Vec3(x[9], x[10], x[11]);
        ba_ += Vec3(x[12], x[13], x[14]);
        q = quat_exp(phi) * q;
        renormalize(q);
        out.correction = true;
        out.rot_enu_rad += phi;
        out.gyro_bias_delta = dbg;
        ekf_.clear_state();
        R = q.toRotationMatrix();
        f = rotate(q, a_scaled - ba_);
    }
    f_prev_ = f;
    t_prev_ = t_ns;

    stride_logic(t_ns, dt, stance, q, out);

    out.pos = p_;
    out.vel = v_;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out.cov_pos[3 * r + c] = ekf_.P(Ekf15::POS + r, Ekf15::POS + c);
    out.heading_rad = heading_of(R);  // R is q's matrix (recomputed after an injection)
}

template <class Filter>
bool FootInsT<Filter>::close_stance(StrideOut& s) {
    const double duration = (last_t_ - stance_start_t_) * 1e-9;
    if (duration < cfg_.min_stance_s) return false;
    const double heading = heading_of(last_stance_q_);
    // The position variance as last applied: at the last stance filter step
    // (the first swing interval may already be deferred: one filter step's noise).
    double cov[3];
    for (int i = 0; i < 3; ++i) cov[i] = ekf_.P(Ekf15::POS + i, Ekf15::POS + i);
    bool emitted = false;
    if (!have_anchor_) {
        have_anchor_ = true;
    } else if (moving_s_ >= cfg_.min_swing_s &&
               std::hypot(last_stance_pos_.x() - anchor_pos_.x(), last_stance_pos_.y() - anchor_pos_.y()) >=
                   cfg_.min_stride_m) {
        s.t_start_ns = anchor_t_;
        s.t_end_ns = last_t_;
        s.displacement = last_stance_pos_ - anchor_pos_;
        s.heading_change_rad = wrap_pi(heading - anchor_heading_);
        std::fill(s.cov_xy, s.cov_xy + 9, 0.0);
        for (int i = 0; i < 3; ++i) s.cov_xy[4 * i] = std::max(cov[i] - anchor_cov_[i], 1e-6);
        if (level_step_) s.stride_class = PN_STRIDE_CLASS_LEVEL;
        else s.stride_class = s.displacement.z() >= 0 ? PN_STRIDE_CLASS_STAIRS_UP : PN_STRIDE_CLASS_STAIRS_DOWN;
        s.index = stride_index_++;
        emitted = true;
    } else {
        return false;  // a stance after a too-short swing: the stride goes on
    }
    anchor_pos_ = last_stance_pos_;
    anchor_heading_ = heading;
    anchor_t_ = last_t_;
    anchor_q_ = last_stance_q_;
    for (int i = 0; i < 3; ++i) anchor_cov_[i] = cov[i];
    moving_s_ = 0;
    max_toe_up_rad_ = 0;
    return emitted;
}

template <class Filter>
void FootInsT<Filter>::begin_stance(int64_t t_ns) {
    in_stance_ = true;
    stance_start_t_ = t_ns;
    if (!have_anchor_) {
        level_step_ = true;
        h_ref_ = levels_.arrive(p_.z());
    } else if (moving_s_ >= cfg_.min_swing_s) {
        // foot-imu-height-update-hupt sec. 2.1: a heel strike (toe-up pitch
        // before the landing) marks a level-floor step; the height then equals
        // the height of the previous stance (eq. (5)), or, for the first level
        // step after stairs, that of a level stood on before at about it.
        const bool after_stairs = !level_step_;
        level_step_ = max_toe_up_rad_ >= heel_strike_rad_;
        h_ref_ = level_step_ && after_stairs ? levels_.arrive(anchor_pos_.z()) : anchor_pos_.z();
    }
}

template <class Filter>
void FootInsT<Filter>::stride_logic(int64_t t_ns, double dt, bool stance, const Quat& q, SampleOut& out) {
    if (stance) {
        last_t_ = t_ns;
        last_stance_pos_ = p_;
        last_stance_q_ = q;
        return;
    }
    if (in_stance_) {
        in_stance_ = false;
        out.stride = close_stance(stride_);
    }
    moving_s_ += dt;
    // Only whether the toe-up pitch reaches heel_strike_deg in this swing
    // matters (begin_stance): once it has, or while the foot has not turned
    // that far from the anchor attitude at all, the pitch is not computed.
    if (have_anchor_ && !(max_toe_up_rad_ >= heel_strike_rad_)) {
        const double vh = std::sqrt(v_.x() * v_.x() + v_.y() * v_.y());
        if (vh > 0.3) {
            const Quat& a = anchor_q_;
            const double cos_half = std::abs(q.w() * a.w() + q.x() * a.x() + q.y() * a.y() + q.z() * a.z());
            if (cos_half < skip_cos_half_) {
                // Pitch about the level axis left of the motion, relative to the
                // attitude at the last stance; toe-up is a negative rotation about it.
                const Vec3 left(-v_.y() / vh, v_.x() / vh, 0.0);
                const double toe_up = -quat_log(q * anchor_q_.conjugate()).dot(left);
                max_toe_up_rad_ = std::max(max_toe_up_rad_, toe_up);
            }
        }
    }
}

template <class Filter>
bool FootInsT<Filter>::finish(StrideOut& s) {
    if (!in_stance_) return false;
    in_stance_ = false;
    return close_stance(s);
}

template class FootInsT<Ekf15>;
template class FootInsT<Ekf15Dense>;

}  // namespace pednav::zupt_ins
