// SPDX-License-Identifier: Apache-2.0
#include "pednav_navmath/strapdown.hpp"

#include <algorithm>

namespace pednav::navmath {

void Strapdown::reset_still() {
    sum_a_.setZero();
    sum_w_.setZero();
    sum_w2_.setZero();
    n_still_ = 0;
    sum_m_.setZero();
    n_mag_ = 0;
}

void Strapdown::align() {
    const Vec3 f = n_still_ > 0 ? Vec3(sum_a_ / n_still_) : last_a_;
    double heading = cfg_.initial_heading_deg * M_PI / 180.0;
    heading_from_mag_ = false;
    if (cfg_.use_magnetometer && n_mag_ > 0) {
        const Vec3 m = sum_m_ / n_mag_;
        const double b = m.norm();
        if (b >= cfg_.mag_min_ut && b <= cfg_.mag_max_ut) {
            heading = magnetic_heading(f, m) + cfg_.declination_deg * M_PI / 180.0;
            heading_from_mag_ = true;
        }
    }
    q_ = level_attitude(f, heading);
    if (cfg_.gyro_bias_from_still && n_still_ > 1) {
        const Vec3 mean = sum_w_ / n_still_;
        const double var = (sum_w2_ / n_still_ - mean.cwiseProduct(mean)).sum();
        if (var < cfg_.bias_still_max_sd_radps * cfg_.bias_still_max_sd_radps) bias_ = mean;
    }
    aligned_ = true;
}

bool Strapdown::on_imu(int64_t t_ns, const Vec3& a, const Vec3& w) {
    if (!aligned_) {
        if (!first_seen_) {
            first_seen_ = true;
            t_first_ = t_ns;
        }
        last_a_ = a;
        const bool still_rate = w.norm() < cfg_.align_gyro_max_radps;
        const bool still_acc = n_still_ == 0 || (a - sum_a_ / n_still_).norm() < cfg_.align_accel_dev_mps2;
        if (still_rate && still_acc) {
            if (n_still_ == 0) t_still_start_ = t_ns;
            sum_a_ += a;
            sum_w_ += w;
            sum_w2_ += w.cwiseProduct(w);
            n_still_ += 1;
            t_still_last_ = t_ns;
            if ((t_ns - t_still_start_) * 1e-9 >= cfg_.align_still_s) align();
        } else if (n_still_ > 0 && (t_still_last_ - t_still_start_) * 1e-9 >= cfg_.align_min_still_s) {
            // Motion starts after a usable still period: align on it, then
            // integrate this sample from the last still one.
            align();
            t_prev_ = t_still_last_;
            w_prev_ = sum_w_ / n_still_;
            have_prev_ = true;
        } else {
            reset_still();
            if (still_rate) {
                t_still_start_ = t_ns;
                sum_a_ += a;
                sum_w_ += w;
                sum_w2_ += w.cwiseProduct(w);
                n_still_ = 1;
                t_still_last_ = t_ns;
            }
        }
        if (!aligned_ && (t_ns - t_first_) * 1e-9 >= cfg_.align_timeout_s) align();
        if (!aligned_) return false;
        if (!have_prev_) {
            t_prev_ = t_ns;
            w_prev_ = w;
            have_prev_ = true;
            return true;
        }
    }

    double dt = (t_ns - t_prev_) * 1e-9;
    dt = std::min(std::max(dt, 0.0), cfg_.max_dt_s);
    if (cfg_.gyro_range_radps > 0 && dt > 0) repair_clipping(w, dt);
    if (dt > 0) {
        const Vec3 w0 = w_prev_ - bias_;
        const Vec3 w1 = w - bias_;
        Vec3 theta = 0.5 * (w0 + w1) * dt;
        if (cfg_.coning) theta += (dt * dt / 12.0) * w0.cross(w1);
        q_ = quat_mul_unit(q_, quat_exp(theta));
    }
    t_prev_ = t_ns;
    if (dt > 0) w_prev2_ = w_prev_;
    w_prev_ = w;
    return true;
}

void Strapdown::repair_clipping(const Vec3& w, double dt) {
    const double level = 0.995 * cfg_.gyro_range_radps;
    for (int i = 0; i < 3; ++i) {
        const double m = std::abs(w[i]);
        if (m >= level) {
            if (clip_len_[i] == 0) {
                clip_entry_slope_[i] = std::max(0.0, (std::abs(w_prev_[i]) - std::abs(w_prev2_[i])) / dt);
                clip_time_[i] = 0.0;
            }
            ++clip_len_[i];
            clip_time_[i] += dt;
            continue;
        }
        if (clip_len_[i] == 0) continue;
        // The run ended: a parabola from the clip level back to it over the run
        // (plus the interval on each side) with the mean of the entry and exit
        // slopes s peaks s T / 4 above the level; the area above is 2/3 T h.
        const double T = clip_time_[i] + dt;
        const double exit_slope = std::max(0.0, (std::abs(w_prev_[i]) - m) / dt);
        const double s = 0.5 * (clip_entry_slope_[i] + exit_slope);
        const double missing = (2.0 / 3.0) * T * (s * T / 4.0);
        Vec3 r = Vec3::Zero();
        r[i] = w_prev_[i] > 0 ? missing : -missing;
        q_ = q_ * quat_exp(r);
        clip_len_[i] = 0;
    }
}

void Strapdown::on_mag(int64_t t_ns, const Vec3& m) {
    if (aligned_ || n_still_ == 0) return;
    if (t_ns < t_still_start_) return;
    sum_m_ += m;
    n_mag_ += 1;
}

void Strapdown::apply_correction(const Vec3& rot, const Vec3& dbias) {
    q_ = quat_mul_unit(quat_exp(rot), q_);
    bias_ += dbias;
}

void Strapdown::set_attitude(const Quat& q) {
    q_ = q.normalized();
    aligned_ = true;
}

}  // namespace pednav::navmath
