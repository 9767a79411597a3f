// SPDX-License-Identifier: Apache-2.0
// A reference strapdown integrator for the simulator's self-test: attitude by
// rotation vector from mid-interval (trapezoidal) rates with the coning term,
// velocity and position by the trapezoidal rule. Exact up to O(dt^2) on smooth
// motion; nothing else (no biases, no filter).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include <pednav_sim/simulate.hpp>

namespace pednav::sim::test {

struct NavState {
    Eigen::Quaterniond q_enu_from_body = Eigen::Quaterniond::Identity();
    Eigen::Vector3d v_enu_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d p_enu_m = Eigen::Vector3d::Zero();
};

inline NavState state_from_truth(const TruthSample& t) {
    NavState s;
    s.q_enu_from_body = Eigen::Quaterniond(t.q_enu_from_body[0], t.q_enu_from_body[1], t.q_enu_from_body[2],
                                           t.q_enu_from_body[3]);
    s.v_enu_mps = Eigen::Vector3d(t.vel_enu_mps);
    s.p_enu_m = Eigen::Vector3d(t.pos_enu_m);
    return s;
}

// Integrates imu[first..last] starting from `start` (the state at imu[first]);
// returns the state at every sample from first to last. Second order: attitude
// by rotation vector from mid-interval rates with the coning term, velocity and
// position by the trapezoidal rule (what a real-time strapdown does).
inline std::vector<NavState> integrate(const std::vector<pn_imu_t>& imu, size_t first, size_t last,
                                       const NavState& start, double gravity_mps2) {
    std::vector<NavState> out{start};
    const Eigen::Vector3d g(0.0, 0.0, -gravity_mps2);
    NavState s = start;
    for (size_t k = first; k < last; ++k) {
        const double dt = static_cast<double>(imu[k + 1].header.t_ns - imu[k].header.t_ns) * 1e-9;
        const Eigen::Vector3d w0(imu[k].gyro_radps), w1(imu[k + 1].gyro_radps);
        const Eigen::Vector3d f0(imu[k].accel_mps2), f1(imu[k + 1].accel_mps2);
        const Eigen::Vector3d phi = 0.5 * (w0 + w1) * dt + w0.cross(w1) * (dt * dt / 12.0);
        const double angle = phi.norm();
        const Eigen::Quaterniond dq = angle > 1e-15
                                          ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle))
                                          : Eigen::Quaterniond::Identity();
        const Eigen::Quaterniond q1 = (s.q_enu_from_body * dq).normalized();
        const Eigen::Vector3d a0 = s.q_enu_from_body * f0 + g, a1 = q1 * f1 + g;
        const Eigen::Vector3d v1 = s.v_enu_mps + 0.5 * (a0 + a1) * dt;
        s.p_enu_m += 0.5 * (s.v_enu_mps + v1) * dt;
        s.v_enu_mps = v1;
        s.q_enu_from_body = q1;
        out.push_back(s);
    }
    return out;
}

// Fourth order: classical Runge-Kutta per sample interval on
// q' = q (x) (0, w) / 2, v' = R f + g, p' = v, with the mid-interval rates from
// cubic interpolation through four neighbouring samples (uniform sampling).
inline std::vector<NavState> integrate_rk4(const std::vector<pn_imu_t>& imu, size_t first, size_t last,
                                           const NavState& start, double gravity_mps2) {
    std::vector<NavState> out{start};
    const Eigen::Vector3d g(0.0, 0.0, -gravity_mps2);
    NavState s = start;
    auto w_at = [&](size_t i) { return Eigen::Vector3d(imu[i].gyro_radps); };
    auto f_at = [&](size_t i) { return Eigen::Vector3d(imu[i].accel_mps2); };
    for (size_t k = first; k < last; ++k) {
        const double dt = static_cast<double>(imu[k + 1].header.t_ns - imu[k].header.t_ns) * 1e-9;
        const size_t km = k > 0 ? k - 1 : k, kp = k + 2 < imu.size() ? k + 2 : k + 1;
        // Cubic midpoint (-1, 9, 9, -1)/16; at the ends of the record, linear.
        const bool cubic = km + 1 == k && kp == k + 2;
        const Eigen::Vector3d w0 = w_at(k), w1 = w_at(k + 1), f0 = f_at(k), f1 = f_at(k + 1);
        Eigen::Vector3d wm = 0.5 * (w0 + w1), fm = 0.5 * (f0 + f1);
        if (cubic) {
            wm = (9.0 * (w0 + w1) - w_at(km) - w_at(kp)) / 16.0;
            fm = (9.0 * (f0 + f1) - f_at(km) - f_at(kp)) / 16.0;
        }
        struct D {
            Eigen::Vector4d dq;  // w, x, y, z
            Eigen::Vector3d dv, dp;
        };
        auto deriv = [&](const Eigen::Vector4d& q, const Eigen::Vector3d& v, const Eigen::Vector3d& w,
                         const Eigen::Vector3d& f) {
            const Eigen::Quaterniond qq(q[0], q[1], q[2], q[3]);
            const Eigen::Quaterniond qw = qq * Eigen::Quaterniond(0.0, w.x(), w.y(), w.z());
            D d;
            d.dq = 0.5 * Eigen::Vector4d(qw.w(), qw.x(), qw.y(), qw.z());
            d.dv = qq.normalized() * f + g;
            d.dp = v;
            return d;
        };
        const Eigen::Vector4d q0(s.q_enu_from_body.w(), s.q_enu_from_body.x(), s.q_enu_from_body.y(),
                                 s.q_enu_from_body.z());
        const D k1 = deriv(q0, s.v_enu_mps, w0, f0);
        const D k2 = deriv(q0 + 0.5 * dt * k1.dq, s.v_enu_mps + 0.5 * dt * k1.dv, wm, fm);
        const D k3 = deriv(q0 + 0.5 * dt * k2.dq, s.v_enu_mps + 0.5 * dt * k2.dv, wm, fm);
        const D k4 = deriv(q0 + dt * k3.dq, s.v_enu_mps + dt * k3.dv, w1, f1);
        const Eigen::Vector4d q1 = q0 + dt / 6.0 * (k1.dq + 2.0 * k2.dq + 2.0 * k3.dq + k4.dq);
        s.v_enu_mps += dt / 6.0 * (k1.dv + 2.0 * k2.dv + 2.0 * k3.dv + k4.dv);
        s.p_enu_m += dt / 6.0 * (k1.dp + 2.0 * k2.dp + 2.0 * k3.dp + k4.dp);
        s.q_enu_from_body = Eigen::Quaterniond(q1[0], q1[1], q1[2], q1[3]).normalized();
        out.push_back(s);
    }
    return out;
}

}  // namespace pednav::sim::test
