// SPDX-License-Identifier: Apache-2.0
#include <pednav_eval/metrics.hpp>

namespace pednav::eval {

const char* truth_kind_name(TruthKind kind) {
    switch (kind) {
        case TruthKind::simulated: return "simulated";
        case TruthKind::footprints: return "footprints";
        case TruthKind::landmarks: return "landmarks";
        case TruthKind::ipin_posi: return "ipin-posi";
        case TruthKind::loop: return "loop";
        case TruthKind::step_events: return "step-events";
    }
    return "?";
}

Metrics evaluate(const Track& raw, const Truth& truth, const EvalOptions& options) {
    Metrics m;
    m.truth_kind = truth_kind_name(truth.kind);
    if (raw.samples.empty()) return m;
    m.alignment = align(raw, truth, options);
    const Track track = apply_alignment(raw, m.alignment);
    const double t_first = track.samples.front().t_s, t_last = track.samples.back().t_s;

    std::vector<double> dx, dy, horiz, heading, height;
    std::vector<int> floor_diff;
    bool floors = true;
    size_t floors_right = 0;
    for (const TruthPoint& p : truth.points) {
        if (p.t_s < t_first - 0.5 || p.t_s > t_last + 0.5) continue;
        const TrackSample s = track.at(p.t_s);
        dx.push_back(s.pos_m[0] - p.x_m);
        dy.push_back(s.pos_m[1] - p.y_m);
        horiz.push_back(std::hypot(dx.back(), dy.back()));
        m.t_s.push_back(p.t_s);
        if (std::isfinite(p.z_m)) height.push_back(s.pos_m[2] - p.z_m);
        if (std::isfinite(p.heading_deg) && std::isfinite(s.heading_deg))
            heading.push_back(std::fabs(angle_diff_deg(s.heading_deg, p.heading_deg)));
        if (p.has_floor && s.has_floor) {
            floor_diff.push_back(s.floor - p.floor);
            floors_right += s.floor == p.floor;
        } else {
            floors = false;
        }
    }
    m.checkpoints = horiz.size();
    m.error_m = horiz;
    m.dx_m = axis_stats(dx);
    m.dy_m = axis_stats(dy);
    m.horizontal_m = error_stats(horiz);
    if (!horiz.empty()) m.final_error_m = horiz.back();
    m.ipin_score_m = floors && !floor_diff.empty() ? ipin_score(horiz, floor_diff) : percentile(horiz, 75.0);
    if (floors && !floor_diff.empty()) m.floor_correct_pct = 100.0 * floors_right / floor_diff.size();
    m.heading_error_deg = error_stats(heading);
    if (!height.empty()) {
        const AxisStats h = axis_stats(height);
        m.height_error_mean_m = h.mean;
        m.height_error_sd_m = h.sd;
    }

    m.distance_m = track.length_m();
    m.truth_distance_m = truth.distance_m;
    if (truth.closed_loop) {
        const double t0 = std::isfinite(truth.loop_start_s) ? truth.loop_start_s : t_first;
        const double t1 = std::isfinite(truth.loop_end_s) ? truth.loop_end_s : t_last;
        const TrackSample a = track.at(t0), b = track.at(t1);
        m.loop_closure_m = std::hypot(b.pos_m[0] - a.pos_m[0], b.pos_m[1] - a.pos_m[1]);
        m.loop_closure_3d_m = std::sqrt(m.loop_closure_m * m.loop_closure_m +
                                        (b.pos_m[2] - a.pos_m[2]) * (b.pos_m[2] - a.pos_m[2]));
        double walked = truth.loop_length_m;
        if (!std::isfinite(walked)) {
            walked = 0.0;
            for (size_t i = 1; i < track.samples.size(); ++i) {
                const TrackSample &p = track.samples[i - 1], &q = track.samples[i];
                if (q.t_s <= t0 || p.t_s >= t1) continue;
                walked += std::hypot(q.pos_m[0] - p.pos_m[0], q.pos_m[1] - p.pos_m[1]);
            }
        }
        m.loop_closure_pct = loop_closure_pct(m.loop_closure_m, walked);
    }
    if (raw.has_steps) m.step_count = static_cast<int>(raw.step_times_s.size());
    m.truth_step_count = truth.step_count;
    for (const Leg& leg : truth.legs) {
        const TrackSample a = track.at(leg.t0_s), b = track.at(leg.t1_s);
        const double len = std::hypot(b.pos_m[0] - a.pos_m[0], b.pos_m[1] - a.pos_m[1]);
        m.leg_lengths_m.push_back(len);
        m.leg_errors_pct.push_back(100.0 * (len - leg.length_m) / leg.length_m);
    }
    return m;
}

}  // namespace pednav::eval
