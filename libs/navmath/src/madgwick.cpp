// SPDX-License-Identifier: Apache-2.0
#include "pednav_navmath/madgwick.hpp"

#include <cmath>
#include <stdexcept>

#include "pednav_navmath/alignment.hpp"
#include "pednav_navmath/heading.hpp"

// The update is also compiled for AVX and picked at load time on x86-64 with
// GCC (as the foot EKF's kernels are): the three-operand encoding saves the
// register copies of SSE2; no FMA contraction, no reassociation, so both
// versions give the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__ELF__)
#define PEDNAV_MADGWICK_CLONES __attribute__((target_clones("avx", "default")))
#else
#define PEDNAV_MADGWICK_CLONES
#endif

namespace pednav::navmath {

Madgwick::Madgwick(const MadgwickConfig& c) : c_(c) {
    if (!(c.gain_radps >= 0)) throw std::invalid_argument("madgwick: gain_radps must not be negative");
    if (!(c.gyro_bias_gain_radps >= 0))
        throw std::invalid_argument("madgwick: gyro_bias_gain_radps must not be negative");
    if (!(c.init_gain_radps >= 0)) throw std::invalid_argument("madgwick: init_gain_radps must not be negative");
    if (!(c.init_s >= 0)) throw std::invalid_argument("madgwick: init_s must not be negative");
    if (!(c.max_dt_s > 0)) throw std::invalid_argument("madgwick: max_dt_s must be positive");
    init_ns_ = static_cast<int64_t>(c.init_s * 1e9);
    sin_decl_ = std::sin(c.declination_deg * M_PI / 180.0);
    cos_decl_ = std::cos(c.declination_deg * M_PI / 180.0);
}

void Madgwick::reset() {
    q_ = Quat::Identity();
    bias_.setZero();
    aligned_ = started_ = false;
    t_ns_ = t0_ns_ = 0;
}

void Madgwick::align(int64_t t_ns, const Vec3& accel_body, double heading_rad) {
    q_ = level_attitude(accel_body, heading_rad);
    aligned_ = started_ = true;
    t_ns_ = t0_ns_ = t_ns;
}

void Madgwick::set_attitude(const Quat& q) {
    q_ = q.normalized();
    aligned_ = true;
}

void Madgwick::set_heading(double heading_rad) {
    // Heading is clockwise, a rotation about up counter-clockwise.
    const double turn = -wrap_pi(heading_rad - heading_of(q_));
    q_ = (Quat(std::cos(0.5 * turn), 0.0, 0.0, std::sin(0.5 * turn)) * q_).normalized();
}

Vec3 Madgwick::up_body() const {
    const double w = q_.w(), x = q_.x(), y = q_.y(), z = q_.z();
    return Vec3(2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y));
}

PEDNAV_MADGWICK_CLONES
bool Madgwick::update(int64_t t_ns, const Vec3& gyro, const Vec3& accel, const Vec3* mag) {
    const double ax = accel.x(), ay = accel.y(), az = accel.z();
    const double an2 = ax * ax + ay * ay + az * az;
    if (!(an2 > 0)) return false;
    if (!started_) {  // aligned by set_attitude: the clock starts here
        started_ = true;
        t_ns_ = t0_ns_ = t_ns;
    }
    double dt = static_cast<double>(t_ns - t_ns_) * 1e-9;
    if (dt > c_.max_dt_s) dt = c_.max_dt_s;
    if (dt < 0) dt = 0;
    t_ns_ = t_ns;
    const double w = q_.w(), x = q_.x(), y = q_.y(), z = q_.z();
    // Every entry of J^T f carries a factor 2, which the normalisation of the
    // gradient removes: the sums below are J^T f / 2.
    const double xx = x * x, yy = y * y, zz = z * z, xy = x * y, xz = x * z, yz = y * z, wx = w * x, wy = w * y,
                 wz = w * z;
    // Row 2 of R(q) (r_ij: ENU axis i, body axis j): up in the body frame.
    const double r20 = 2 * (xz - wy), r21 = 2 * (yz + wx), r22 = 1 - 2 * (xx + yy);
    const double ia = 1.0 / std::sqrt(an2);
    // Gravity part, d = (0, 0, 1): e = R^T d - a_hat = row 2 of R - a_hat.
    const double e0 = r20 - ax * ia, e1 = r21 - ay * ia, e2 = r22 - az * ia;
    double gw = x * e1 - y * e0;
    double gx = z * e0 + w * e1 - 2 * x * e2;
    double gy = z * e1 - w * e0 - 2 * y * e2;
    double gz = x * e0 + y * e1;
    if (mag) {
        const double mx0 = mag->x(), my0 = mag->y(), mz0 = mag->z();
        const double mn2 = mx0 * mx0 + my0 * my0 + mz0 * mz0;
        if (mn2 > 0) {
            const double im = 1.0 / std::sqrt(mn2);
            const double mx = mx0 * im, my = my0 * im, mz = mz0 * im;
            const double r00 = 1 - 2 * (yy + zz), r01 = 2 * (xy - wz), r02 = 2 * (xz + wy);
            const double r10 = 2 * (xy + wz), r11 = 1 - 2 * (xx + zz), r12 = 2 * (yz - wx);
            // The field in ENU, h = R m; the reference keeps its dip and points at magnetic north.
            const double he = r00 * mx + r01 * my + r02 * mz, hn = r10 * mx + r11 * my + r12 * mz,
                         hu = r20 * mx + r21 * my + r22 * mz;
            const double bh = std::sqrt(he * he + hn * hn);
            const double dx = bh * sin_decl_, dy = bh * cos_decl_, dz = hu;
            // f = R^T d - m_hat, body_i = dx r0i + dy r1i + dz r2i.
            const double f0 = dx * r00 + dy * r10 + dz * r20 - mx;
            const double f1 = dx * r01 + dy * r11 + dz * r21 - my;
            const double f2 = dx * r02 + dy * r12 + dz * r22 - mz;
            // sum_j d_j G_j(f) / 2, G_j(f) = sum_i f_i d(r_ji)/dq (the rows of R differentiated).
            gw += dy * (z * f0 - x * f2) + dz * (x * f1 - y * f0);
            gx += dy * (y * f0 - 2 * x * f1 - w * f2) + dz * (z * f0 + w * f1 - 2 * x * f2);
            gy += dy * (x * f0 + z * f2) + dz * (z * f1 - w * f0 - 2 * y * f2);
            gz += dy * (w * f0 - 2 * z * f1 + y * f2) + dz * (x * f0 + y * f1);
            if (sin_decl_ != 0.0) {
                gw += dx * (y * f2 - z * f1);
                gx += dx * (y * f1 + z * f2);
                gy += dx * (x * f1 + w * f2 - 2 * y * f0);
                gz += dx * (x * f2 - 2 * z * f0 - w * f1);
            }
        }
    }
    const double g2 = gw * gw + gx * gx + gy * gy + gz * gz;
    const double beta = t_ns - t0_ns_ < init_ns_ ? c_.init_gain_radps : c_.gain_radps;
    double sw = 0, sx = 0, sy = 0, sz = 0;  // beta grad / |grad|
    if (g2 > 0) {
        const double ig = 1.0 / std::sqrt(g2);
        if (c_.gyro_bias_gain_radps > 0) {
            // omega_eps = 2 q* (x) grad_hat, vector part.
            const double k = 2 * ig * c_.gyro_bias_gain_radps * dt;
            bias_.x() += k * (w * gx - x * gw - y * gz + z * gy);
            bias_.y() += k * (w * gy + x * gz - y * gw - z * gx);
            bias_.z() += k * (w * gz - x * gy + y * gx - z * gw);
        }
        const double bg = beta * ig;
        sw = bg * gw, sx = bg * gx, sy = bg * gy, sz = bg * gz;
    }
    const double ox = gyro.x() - bias_.x(), oy = gyro.y() - bias_.y(), oz = gyro.z() - bias_.z();
    // q += (1/2 q (x) (0, omega) - beta grad_hat) dt, normalised.
    const double hdt = 0.5 * dt;
    const double nw = w + (-x * ox - y * oy - z * oz) * hdt - sw * dt;
    const double nx = x + (w * ox + y * oz - z * oy) * hdt - sx * dt;
    const double ny = y + (w * oy - x * oz + z * ox) * hdt - sy * dt;
    const double nz = z + (w * oz + x * oy - y * ox) * hdt - sz * dt;
    const double in = 1.0 / std::sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
    q_ = Quat(nw * in, nx * in, ny * in, nz * in);
    return true;
}

}  // namespace pednav::navmath
