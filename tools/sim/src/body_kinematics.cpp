// SPDX-License-Identifier: Apache-2.0
#include "body_kinematics.hpp"

#include <algorithm>
#include <cmath>

#include "path_heading.hpp"
#include "profiles.hpp"
#include "trunk_path.hpp"

namespace pednav::sim::detail {

namespace {

constexpr double kPauseS = 1.0;  // a stance longer than this is standing still
constexpr double kWarpS = 0.4;   // a bout's start and end are eased in and out over this long

// Time warp easing a bout in: tau(t) starts at the bout's first knot t0 with
// tau' = tau'' = 0 at t = t0 - kWarpS / 2 and joins tau = t at t0 + kWarpS / 2
// (tau' is the rest-to-rest transition, so tau is its integral); mirrored at the end.
Profile warp(double t, double t0, double t1) {
    const double D = kWarpS;
    auto ease = [D](double u) {  // integral of transition(u) and its derivatives, u in [0, 1]
        const double u2 = u * u, u4 = u2 * u2, u5 = u4 * u;
        const Profile tr = transition(u);
        return Profile{D * (7.0 * u5 - 14.0 * u5 * u + 10.0 * u5 * u2 - 2.5 * u4 * u4), tr.f, tr.df / D};
    };
    if (t < t0 + 0.5 * D) {
        const double u = std::max(0.0, (t - (t0 - 0.5 * D)) / D);
        const Profile e = ease(u);
        return {t0 + e.f, e.df, e.ddf};
    }
    if (t > t1 - 0.5 * D) {
        const double u = std::max(0.0, ((t1 + 0.5 * D) - t) / D);
        const Profile e = ease(u);
        return {t1 - e.f, e.df, -e.ddf};
    }
    return {t, 1.0, 0.0};
}

// f(tau(t)) differentiated with respect to t.
Profile chain(const Profile& f, const Profile& tau) {
    return {f.f, f.df * tau.df, f.ddf * tau.df * tau.df + f.df * tau.ddf};
}

// g = A w(t) h(phase(t)) with h = sin(k pi phase + offset): value and derivatives.
Profile oscillation(double A, const Profile& w, const Profile& ph, double k, double offset) {
    const double arg = k * M_PI * ph.f + offset, kk = k * M_PI;
    const double h = std::sin(arg), h1 = kk * std::cos(arg), h2 = -kk * kk * std::sin(arg);
    return {A * w.f * h, A * (w.df * h + w.f * h1 * ph.df),
            A * (w.ddf * h + 2.0 * w.df * h1 * ph.df + w.f * (h2 * ph.df * ph.df + h1 * ph.ddf))};
}

Profile product(const Profile& a, const Profile& b) {
    return {a.f * b.f, a.df * b.f + a.f * b.df, a.ddf * b.f + 2.0 * a.df * b.df + a.f * b.ddf};
}

// The rise of the trunk over a step whose horizontal chord is step_m, on a
// leg of length leg_length_m (the inverted pendulum): l - sqrt(l^2 - (L/2)^2).
double pendulum_rise_m(double leg_length_m, double step_m) {
    const double half_m = std::min(0.5 * step_m, leg_length_m);
    return leg_length_m - std::sqrt(leg_length_m * leg_length_m - half_m * half_m);
}

}  // namespace

BodyKinematics::BodyKinematics(const GaitPlan& plan, BodyShape shape) : shape_(shape) {
    const double rise_nominal_m = pendulum_rise_m(shape_.leg_length_m, plan.step_nominal_m);
    // Split the foot timeline into pauses (long stances) and walking bouts.
    size_t i = 0;
    double yaw_now = plan.prints[0].yaw_enu_rad;
    // Standing at the footprint of phase k from t0 to the phase's end, facing
    // the next bout's direction by then.
    const auto add_pause = [&](size_t k, double t0) {
        const FootPhase& ph = plan.phases[k];
        Span s;
        s.t0 = t0;
        s.t1 = ph.t1_s;
        s.p = plan.prints[ph.to].p_enu_m;
        s.segment = plan.prints[ph.to].segment;
        s.yaw0 = s.yaw1 = yaw_now;
        if (k + 1 < plan.phases.size()) {
            const FootPhase& next = plan.phases[k + 1];
            const Eigen::Vector3d d = plan.prints[next.to].p_enu_m - plan.prints[next.from].p_enu_m;
            if (d.head<2>().norm() > 1e-9) s.yaw1 = yaw_now + wrap_pi(std::atan2(d.y(), d.x()) - yaw_now);
        }
        yaw_now = s.yaw1;
        spans_.push_back(std::move(s));
    };
    while (i < plan.phases.size()) {
        const FootPhase& ph = plan.phases[i];
        const bool pause =
            !ph.swing && (i == 0 || i + 1 == plan.phases.size() || ph.t1_s - ph.t0_s > kPauseS);
        if (pause) {
            add_pause(i, ph.t0_s);
            ++i;
            continue;
        }
        // A bout: from the end of the previous pause to the landing before the next pause.
        Span s;
        s.walking = true;
        s.t0 = ph.t0_s - 0.5 * kWarpS;
        spans_.back().t1 = s.t0;
        std::vector<double> kt{ph.t0_s}, kx, ky, kz, kphase{0.0};
        std::vector<bool> level_step;  // per step (knot interval): on a level stride
        const Eigen::Vector3d p0 = plan.prints[ph.from].p_enu_m;
        std::vector<Eigen::Vector3d> kp{p0};
        s.segment_at_knot.push_back(plan.prints[ph.from].segment);
        double t_prev = ph.t0_s;
        size_t j = i;
        for (; j < plan.phases.size(); ++j) {
            const FootPhase& q = plan.phases[j];
            if (!q.swing) {
                const bool next_pause = j + 1 == plan.phases.size() || q.t1_s - q.t0_s > kPauseS;
                if (next_pause) break;
                continue;
            }
            // The other foot lands halfway (in time and place), then this foot.
            const Eigen::Vector3d a = plan.prints[q.from].p_enu_m, b = plan.prints[q.to].p_enu_m;
            level_step.insert(level_step.end(), 2, plan.prints[q.to].kind == StrideKind::level);
            kt.push_back(0.5 * (t_prev + q.t1_s));
            kp.emplace_back(0.5 * (a + b));
            s.segment_at_knot.push_back(plan.prints[q.to].segment);
            kt.push_back(q.t1_s);
            kp.push_back(b);
            s.segment_at_knot.push_back(plan.prints[q.to].segment);
            t_prev = q.t1_s;
        }
        s.t1 = t_prev + 0.5 * kWarpS;
        // The trunk's path: the landings smoothed (the centre of mass rounds a corner), heights kept.
        const std::vector<Eigen::Vector3d> kc = trunk_knots(kp);
        for (size_t k = 0; k < kc.size(); ++k) {
            kx.push_back(kc[k].x());
            ky.push_back(kc[k].y());
            kz.push_back(kc[k].z());
            if (k > 0) kphase.push_back(static_cast<double>(k));
        }
        // Each level step's bounce over bounce_m: the pendulum's rise over the trunk's own chord, knot to
        // knot (at a corner shorter than the feet's spacing), against the nominal step's; stairs keep 1.
        std::vector<double> step_scale;
        for (size_t k = 1; k < kc.size(); ++k) {
            const double chord_m = (kc[k] - kc[k - 1]).head<2>().norm();
            step_scale.push_back(level_step[k - 1] && rise_nominal_m > 0.0
                                     ? pendulum_rise_m(shape_.leg_length_m, chord_m) / rise_nominal_m
                                     : 1.0);
        }
        for (size_t k = 1; k < kt.size(); ++k) steps_.push_back(kt[k]);
        s.knot_t = kt;
        s.x = ClampedSpline(kt, kx);
        s.y = ClampedSpline(kt, ky);
        s.z = ClampedSpline(kt, kz);
        // The yaw: the path's own direction.
        const HeadingSamples heading = path_heading(kt, kc, s.x, s.y, yaw_now);
        yaw_now = heading.yaw_rad.back();
        s.yaw = ClampedSpline(heading.t_s, heading.yaw_rad);
        s.phase = ClampedSpline(kt, kphase);
        // The bounce's scale against the phase: each step's value at its middle, held to both ends.
        std::vector<double> sphase{0.0}, sscale{step_scale.front()};
        for (size_t k = 0; k < step_scale.size(); ++k) {
            sphase.push_back(static_cast<double>(k) + 0.5);
            sscale.push_back(step_scale[k]);
        }
        sphase.push_back(static_cast<double>(step_scale.size()));
        sscale.push_back(step_scale.back());
        s.bounce_scale = ClampedSpline(sphase, sscale);
        s.ramp_in_s = kt[1] - kt[0];
        s.ramp_out_s = kt[kt.size() - 1] - kt[kt.size() - 2];
        const double bout_end_s = s.t1;
        spans_.push_back(std::move(s));
        i = j;
        // The pause that follows starts at the last landing.
        if (i < plan.phases.size()) {
            add_pause(i, bout_end_s);
            ++i;
        }
    }
}

KinState BodyKinematics::at(double t_s) {
    while (cursor_ + 1 < spans_.size() && t_s >= spans_[cursor_].t1) ++cursor_;
    const Span& s = spans_[cursor_];
    KinState k;
    if (!s.walking) {
        // Standing; turning on the spot over the last 2 s of the pause when the next bout goes elsewhere.
        const double turn_s = std::min(2.0, s.t1 - s.t0);
        const Profile tr = scaled(transition, t_s, s.t1 - turn_s, turn_s);
        const double dyaw = s.yaw1 - s.yaw0;
        k.p_enu_m = s.p + Eigen::Vector3d(0.0, 0.0, shape_.height_m);
        k.yaw_enu_rad = s.yaw0 + dyaw * tr.f;
        k.stance = 1;
        k.segment = s.segment;
        if (has_hand_terms()) {
            const Profile still{0.0, 0.0, 0.0};
            add_hand_attitude(t_s, {k.yaw_enu_rad, dyaw * tr.df, dyaw * tr.ddf}, still, still, k);
            return k;
        }
        euler_zyx(k.yaw_enu_rad, 0.0, 0.0, dyaw * tr.df, 0.0, 0.0, k.R_enu_body, k.w_body_radps);
        return k;
    }
    // Everything walks on the eased time tau(t); knots span [kt0, kt1].
    const double kt0 = s.knot_t.front(), kt1 = s.knot_t.back();
    const Profile tau = warp(t_s, kt0, kt1);
    const Profile x = chain(s.x.at(tau.f), tau), y = chain(s.y.at(tau.f), tau), z = chain(s.z.at(tau.f), tau);
    const Profile yaw = chain(s.yaw.at(tau.f), tau), ph = chain(s.phase.at(tau.f), tau);
    // Envelope: oscillations fade in over the first step and out over the last.
    const Profile w_in = chain(scaled(transition, tau.f, kt0, s.ramp_in_s), tau);
    Profile w_out = chain(scaled(transition, tau.f, kt1 - s.ramp_out_s, s.ramp_out_s), tau);
    w_out = {1.0 - w_out.f, -w_out.df, -w_out.ddf};
    const Profile w = product(w_in, w_out);
    // Bounce: the step's amplitude (a function of the phase) times the oscillation, lowest at each landing.
    const Profile bounce_scale = chain(s.bounce_scale.at(ph.f), ph);
    const Profile bounce = product(bounce_scale, oscillation(shape_.bounce_m, w, ph, 2.0, -0.5 * M_PI));
    const Profile sway = oscillation(shape_.sway_m, w, ph, 1.0, 0.0);
    const Profile pitch = oscillation(shape_.pitch_rad, w, ph, 2.0, 0.0);
    const Profile roll = oscillation(shape_.roll_rad, w, ph, 1.0, 0.0);

    // Lateral sway along the left normal n of the walking direction: (y n)'' = y'' n + 2 y' n' + y n''.
    const Eigen::Vector3d tang(std::cos(yaw.f), std::sin(yaw.f), 0.0),
        n(-std::sin(yaw.f), std::cos(yaw.f), 0.0);
    const Eigen::Vector3d dn = -yaw.df * tang;
    const Eigen::Vector3d ddn = -yaw.ddf * tang - yaw.df * yaw.df * n;
    k.p_enu_m = Eigen::Vector3d(x.f, y.f, z.f + shape_.height_m + bounce.f) + sway.f * n;
    k.v_enu_mps = Eigen::Vector3d(x.df, y.df, z.df + bounce.df) + sway.df * n + sway.f * dn;
    k.a_enu_mps2 =
        Eigen::Vector3d(x.ddf, y.ddf, z.ddf + bounce.ddf) + sway.ddf * n + 2.0 * sway.df * dn + sway.f * ddn;
    k.yaw_enu_rad = yaw.f;
    k.stance = 0;
    // Segment: the knot interval the time falls in.
    const size_t idx =
        static_cast<size_t>(std::upper_bound(s.knot_t.begin(), s.knot_t.end(), tau.f) - s.knot_t.begin());
    k.segment = s.segment_at_knot[std::min(idx, s.segment_at_knot.size() - 1)];
    if (has_hand_terms()) {
        // Surge along the walking direction t: (s t)'' = s'' t + 2 s' t' + s t''.
        const Profile surge = oscillation(shape_.surge_m, w, ph, 2.0, 0.0);
        const Eigen::Vector3d dt = yaw.df * n, ddt = yaw.ddf * n - yaw.df * yaw.df * tang;
        // The hand: lateral with the shoulders at half the step frequency (a quarter period after the
        // trunk's sway), vertical at the step frequency.
        const Profile hand_lat = oscillation(shape_.hand_sway_m, w, ph, 1.0, 0.5 * M_PI);
        const Profile hand_up = oscillation(shape_.hand_sway_m, w, ph, 2.0, 0.75 * M_PI);
        k.p_enu_m += surge.f * tang + hand_lat.f * n + Eigen::Vector3d(0.0, 0.0, hand_up.f);
        k.v_enu_mps += surge.df * tang + surge.f * dt + hand_lat.df * n + hand_lat.f * dn +
                       Eigen::Vector3d(0.0, 0.0, hand_up.df);
        k.a_enu_mps2 += surge.ddf * tang + 2.0 * surge.df * dt + surge.f * ddt + hand_lat.ddf * n +
                        2.0 * hand_lat.df * dn + hand_lat.f * ddn + Eigen::Vector3d(0.0, 0.0, hand_up.ddf);
        add_hand_attitude(t_s, yaw, pitch, roll, k);
        return k;
    }
    euler_zyx(yaw.f, pitch.f, roll.f, yaw.df, pitch.df, roll.df, k.R_enu_body, k.w_body_radps);
    return k;
}

// The attitude with the handheld terms: the constant pitch and the slow
// wobble (three sines at incommensurate frequencies per axis) on top of the
// body's yaw, pitch and roll.
void BodyKinematics::add_hand_attitude(double t_s, const Profile& yaw, const Profile& pitch, const Profile& roll,
                                       KinState& k) const {
    const double A = shape_.wobble_rad;
    const auto wobble = [A, t_s](double f1, double f2, double phase) {
        const double w1 = 2.0 * M_PI * f1, w2 = 2.0 * M_PI * f2;
        return Profile{A * (0.6 * std::sin(w1 * t_s + phase) + 0.4 * std::sin(w2 * t_s + 2.0 * phase)),
                       A * (0.6 * w1 * std::cos(w1 * t_s + phase) + 0.4 * w2 * std::cos(w2 * t_s + 2.0 * phase)),
                       -A * (0.6 * w1 * w1 * std::sin(w1 * t_s + phase) +
                             0.4 * w2 * w2 * std::sin(w2 * t_s + 2.0 * phase))};
    };
    const Profile wy = wobble(0.23, 0.53, 0.3), wp = wobble(0.31, 0.61, 1.1), wr = wobble(0.27, 0.47, 2.0);
    euler_zyx(yaw.f + wy.f, pitch.f + shape_.pitch_offset_rad + wp.f, roll.f + wr.f, yaw.df + wy.df,
              pitch.df + wp.df, roll.df + wr.df, k.R_enu_body, k.w_body_radps);
}

}  // namespace pednav::sim::detail
