// SPDX-License-Identifier: Apache-2.0
#include "foot_kinematics.hpp"

#include <cmath>

#include "profiles.hpp"

namespace pednav::sim::detail {

KinState FootKinematics::at(double t_s) {
    while (cursor_ + 1 < plan_.phases.size() && t_s >= plan_.phases[cursor_].t1_s) ++cursor_;
    const FootPhase& ph = plan_.phases[cursor_];
    KinState s;
    if (!ph.swing) {
        const Footprint& fp = plan_.prints[ph.to];
        s.p_enu_m = fp.p_enu_m;
        s.yaw_enu_rad = fp.yaw_enu_rad;
        s.segment = fp.segment;
        s.stance = 1;
        euler_zyx(fp.yaw_enu_rad, 0.0, 0.0, 0.0, 0.0, 0.0, s.R_enu_body, s.w_body_radps);
        return s;
    }
    const Footprint& a = plan_.prints[ph.from];
    const Footprint& b = plan_.prints[ph.to];
    const double T = ph.t1_s - ph.t0_s;
    const double x = t_s - ph.t0_s;  // time into the swing
    s.stance = 0;
    s.segment = b.segment;

    // Horizontal: rest-to-rest along the chord.
    const Eigen::Vector3d d = b.p_enu_m - a.p_enu_m;
    const Profile h = scaled(transition, x, 0.0, T);
    s.p_enu_m = a.p_enu_m + h.f * Eigen::Vector3d(d.x(), d.y(), 0.0);
    s.v_enu_mps = h.df * Eigen::Vector3d(d.x(), d.y(), 0.0);
    s.a_enu_mps2 = h.ddf * Eigen::Vector3d(d.x(), d.y(), 0.0);

    // Vertical: climb (early on the way up, late on the way down) plus an arc.
    Profile climb = h;
    double clearance = shape_.clearance_m;
    if (b.kind == StrideKind::stairs_up) {
        climb = scaled(transition, x, 0.0, 0.7 * T);
        clearance = shape_.stairs_clearance_m;
    } else if (b.kind == StrideKind::stairs_down) {
        climb = scaled(transition, x, 0.3 * T, 0.7 * T);
        clearance = shape_.stairs_clearance_m;
    }
    const Profile arc = scaled(bump, x, 0.0, T);
    s.p_enu_m.z() = a.p_enu_m.z() + d.z() * climb.f + clearance * arc.f;
    s.v_enu_mps.z() = d.z() * climb.df + clearance * arc.df;
    s.a_enu_mps2.z() = d.z() * climb.ddf + clearance * arc.ddf;
    if (shape_.heel_strike_mps2 > 0.0 && b.kind == StrideKind::level) {
        // Landing transient: two cycles of a vertical oscillation under a bump window,
        // from 86 % to 96 % of the swing (part of the trajectory, so still exact).
        const double x0 = 0.86 * T, D = 0.10 * T, w = 2.0 * M_PI * 2.0 / D;
        const double A = shape_.heel_strike_mps2 / (w * w);
        const Profile win = scaled(bump, x, x0, D);
        const double sn = std::sin(w * (x - x0)), cs = std::cos(w * (x - x0));
        s.p_enu_m.z() += A * win.f * sn;
        s.v_enu_mps.z() += A * (win.df * sn + win.f * w * cs);
        s.a_enu_mps2.z() += A * (win.ddf * sn + 2.0 * win.df * w * cs - win.f * w * w * sn);
    }

    // Attitude: yaw turns with the stride; pitch toes-down at toe-off, toes-up
    // at heel strike on level floors; a little roll in swing.
    const double dyaw = wrap_pi(b.yaw_enu_rad - a.yaw_enu_rad);
    Profile pitch;
    if (b.kind == StrideKind::level) {
        const Profile toe = scaled(bump, x, 0.0, 0.6 * T);
        const Profile heel = scaled(bump, x, 0.55 * T, 0.45 * T);
        pitch.f = shape_.toe_off_pitch_rad * toe.f - shape_.heel_strike_pitch_rad * heel.f;
        pitch.df = shape_.toe_off_pitch_rad * toe.df - shape_.heel_strike_pitch_rad * heel.df;
    } else {
        const Profile toe = scaled(bump, x, 0.0, T);
        pitch.f = shape_.stairs_pitch_rad * toe.f;
        pitch.df = shape_.stairs_pitch_rad * toe.df;
    }
    s.yaw_enu_rad = a.yaw_enu_rad + dyaw * h.f;
    euler_zyx(s.yaw_enu_rad, pitch.f, shape_.roll_rad * arc.f, dyaw * h.df, pitch.df,
              shape_.roll_rad * arc.df, s.R_enu_body, s.w_body_radps);
    return s;
}

}  // namespace pednav::sim::detail
