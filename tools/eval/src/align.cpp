// SPDX-License-Identifier: Apache-2.0
#include <stdexcept>

#include <pednav_eval/metrics.hpp>

namespace pednav::eval {

Alignment parse_alignment(const std::string& name) {
    if (name == "none") return Alignment::none;
    if (name == "start") return Alignment::start_point;
    if (name == "first-segment") return Alignment::first_segment;
    if (name == "fitted") return Alignment::fitted;
    throw std::runtime_error("unknown alignment '" + name + "' (none, start, first-segment, fitted)");
}

const char* alignment_name(Alignment a) {
    switch (a) {
        case Alignment::none: return "none";
        case Alignment::start_point: return "start";
        case Alignment::first_segment: return "first-segment";
        case Alignment::fitted: return "fitted";
    }
    return "?";
}

double procrustes_rotation_rad(const std::vector<std::array<double, 2>>& a,
                               const std::vector<std::array<double, 2>>& b) {
    // Minimise sum |R a_i - b_i|^2 over rotations R(theta): theta = atan2(sum a x b, sum a . b).
    double s_cross = 0.0, s_dot = 0.0;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        s_cross += a[i][0] * b[i][1] - a[i][1] * b[i][0];
        s_dot += a[i][0] * b[i][0] + a[i][1] * b[i][1];
    }
    return std::atan2(s_cross, s_dot);
}

namespace {

// The truth's start: the known start point at the track's first time, or the first checkpoint.
bool truth_start(const Track& track, const Truth& truth, double& t, double& x, double& y, double& z) {
    if (std::isfinite(truth.start_x_m) && std::isfinite(truth.start_y_m)) {
        t = track.samples.front().t_s;
        x = truth.start_x_m;
        y = truth.start_y_m;
        z = NAN;
        return true;
    }
    if (truth.points.empty()) return false;
    t = truth.points.front().t_s;
    x = truth.points.front().x_m;
    y = truth.points.front().y_m;
    z = truth.points.front().z_m;
    return true;
}

}  // namespace

AlignmentResult align(const Track& track, const Truth& truth, const EvalOptions& o) {
    AlignmentResult r;
    r.mode = o.alignment;
    if (o.alignment == Alignment::none || track.samples.empty()) return r;
    double t0 = 0.0, x0 = 0.0, y0 = 0.0, z0 = NAN;
    if (!truth_start(track, truth, t0, x0, y0, z0)) {
        // A loop or step events only: nothing to align to but the track's own start.
        const TrackSample s = track.samples.front();
        r.from_m[0] = r.to_m[0] = s.pos_m[0];
        r.from_m[1] = r.to_m[1] = s.pos_m[1];
        return r;
    }
    const TrackSample s0 = track.at(t0);
    r.from_m[0] = s0.pos_m[0];
    r.from_m[1] = s0.pos_m[1];
    r.to_m[0] = x0;
    r.to_m[1] = y0;
    r.z_offset_m = std::isfinite(z0) ? z0 - s0.pos_m[2] : 0.0;
    const bool start_is_point = !(std::isfinite(truth.start_x_m) && std::isfinite(truth.start_y_m));
    const size_t first = start_is_point ? 1 : 0;  // checkpoints after the start
    if (o.alignment == Alignment::first_segment) {
        for (size_t k = first; k < truth.points.size(); ++k) {
            const TruthPoint& p = truth.points[k];
            if (std::hypot(p.x_m - x0, p.y_m - y0) < o.first_segment_m) continue;
            const TrackSample s = track.at(p.t_s);
            const double a_truth = std::atan2(p.y_m - y0, p.x_m - x0);
            const double a_track = std::atan2(s.pos_m[1] - s0.pos_m[1], s.pos_m[0] - s0.pos_m[0]);
            r.rotation_deg = angle_diff_deg(a_truth * 180.0 / M_PI, a_track * 180.0 / M_PI);
            break;
        }
    } else if (o.alignment == Alignment::fitted) {
        std::vector<std::array<double, 2>> a, b;
        for (size_t k = first; k < truth.points.size(); ++k) {
            if (o.fit_points > 0 && a.size() >= o.fit_points) break;
            const TruthPoint& p = truth.points[k];
            const TrackSample s = track.at(p.t_s);
            a.push_back({s.pos_m[0] - s0.pos_m[0], s.pos_m[1] - s0.pos_m[1]});
            b.push_back({p.x_m - x0, p.y_m - y0});
        }
        r.rotation_deg = procrustes_rotation_rad(a, b) * 180.0 / M_PI;
    }
    return r;
}

Track apply_alignment(const Track& track, const AlignmentResult& a) {
    Track out = track;
    const double th = a.rotation_deg * M_PI / 180.0, c = std::cos(th), s = std::sin(th);
    for (TrackSample& p : out.samples) {
        const double x = p.pos_m[0] - a.from_m[0], y = p.pos_m[1] - a.from_m[1];
        p.pos_m[0] = c * x - s * y + a.to_m[0];
        p.pos_m[1] = s * x + c * y + a.to_m[1];
        p.pos_m[2] += a.z_offset_m;
        // Heading is clockwise, the rotation counter-clockwise.
        if (std::isfinite(p.heading_deg))
            p.heading_deg = std::fmod(p.heading_deg - a.rotation_deg + 720.0, 360.0);
    }
    return out;
}

}  // namespace pednav::eval
