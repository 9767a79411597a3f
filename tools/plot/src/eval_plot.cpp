// SPDX-License-Identifier: Apache-2.0
#include <pednav_plot/eval_plot.hpp>

#include <cstdio>

namespace pednav::plot {

WalkPlot walk_plot(const std::string& title, const eval::Track& raw, const eval::Truth* truth,
                   const eval::Metrics* metrics) {
    WalkPlot p;
    p.title = title;
    const eval::Track track = metrics ? eval::apply_alignment(raw, metrics->alignment) : raw;
    if (truth) {
        for (const eval::WallLine& w : truth->walls) p.map.walls.push_back(w.points_m);
        Series t;
        t.label = std::string("truth (") + eval::truth_kind_name(truth->kind) + ")";
        t.color = "#2ca02c";
        for (const eval::TruthPoint& q : truth->points) t.points.push_back({q.x_m, q.y_m});
        if (truth->kind == eval::TruthKind::simulated) {
            t.width_px = 2.5;
        } else {
            t.width_px = 0.0;
            t.markers = true;
        }
        if (!t.points.empty()) p.map.series.push_back(t);
    }
    Series est;
    est.label = "estimate";
    est.color = "#1f77b4";
    est.width_px = 1.5;
    for (const eval::TrackSample& s : track.samples) est.points.push_back({s.pos_m[0], s.pos_m[1]});
    p.map.series.push_back(est);
    if (metrics && !metrics->t_s.empty()) {
        Series e;
        char label[96];
        std::snprintf(label, sizeof label, "horizontal error (mean %.2f m, p75 %.2f m)",
                      metrics->horizontal_m.mean, metrics->horizontal_m.p75);
        e.label = label;
        e.color = "#d62728";
        for (size_t i = 0; i < metrics->t_s.size(); ++i)
            e.points.push_back({metrics->t_s[i], metrics->error_m[i]});
        e.markers = metrics->t_s.size() < 200;
        p.error.series.push_back(e);
    }
    return p;
}

}  // namespace pednav::plot
