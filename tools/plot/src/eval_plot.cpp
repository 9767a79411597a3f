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

std::vector<MapPanel> walk_floor_panels(const eval::Track& raw, const eval::Truth* truth, const eval::Metrics* metrics,
                                        const indoor_map::Map& map, const std::vector<std::string>& landmark_names) {
    // The series of the plain figure, with the floor of each point.
    const WalkPlot flat = walk_plot("", raw, truth, metrics);
    const eval::Track track = metrics ? eval::apply_alignment(raw, metrics->alignment) : raw;
    std::vector<FloorSeries> series;
    size_t k = 0;
    if (truth && !truth->points.empty()) {
        FloorSeries t{flat.map.series[k++], {}};
        for (const eval::TruthPoint& q : truth->points) t.floors.push_back(q.has_floor ? q.floor : 0);
        series.push_back(std::move(t));
    }
    FloorSeries est{flat.map.series[k], {}};
    for (const eval::TrackSample& s : track.samples) est.floors.push_back(s.has_floor ? s.floor : 0);
    series.push_back(std::move(est));
    return floor_panels(map, landmark_names, series);
}

}  // namespace pednav::plot
