// SPDX-License-Identifier: Apache-2.0
#include <pednav_plot/walk_plot.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pednav::plot {

namespace {

constexpr double kMaxPoints = 4000.0;  // per series: thinned beyond this (a plot, not a data file)

struct Box {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    void add(const Point& p) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return;
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    }
    bool valid() const { return x0 <= x1 && y0 <= y1; }
};

std::vector<Point> thin(const std::vector<Point>& pts) {
    if (pts.size() <= kMaxPoints) return pts;
    const size_t step = static_cast<size_t>(std::ceil(pts.size() / kMaxPoints));
    std::vector<Point> out;
    for (size_t i = 0; i < pts.size(); i += step) out.push_back(pts[i]);
    if (out.back() != pts.back()) out.push_back(pts.back());
    return out;
}

std::string label_of(double v) {
    char buf[32];
    if (std::fabs(v) < 1e-9) v = 0.0;
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

const Stroke kAxis{"#444444", 1.0, false, 1.0};
const Stroke kGrid{"#dddddd", 0.8, false, 1.0};
const Stroke kWall{"#888888", 1.2, false, 1.0};

void legend(Svg& svg, const std::vector<Series>& series, double right_px, double top_px) {
    double y = top_px + 14.0;
    double width = 0.0;
    for (const Series& s : series) width = std::max(width, 7.0 * static_cast<double>(s.label.size()));
    const double x = right_px - width - 40.0;
    size_t shown = 0;
    for (const Series& s : series) shown += !s.label.empty();
    if (shown == 0) return;
    svg.rect({x - 6.0, top_px + 2.0}, width + 42.0, 16.0 * static_cast<double>(shown) + 6.0, "#ffffff",
             Stroke{"#cccccc", 0.8, false, 0.9});
    for (const Series& s : series) {
        if (s.label.empty()) continue;
        if (s.markers && s.width_px <= 0.0)
            svg.circle({x + 12.0, y - 4.0}, 3.0, s.color);
        else
            svg.line({x, y - 4.0}, {x + 24.0, y - 4.0},
                     Stroke{s.color, std::max(1.5, s.width_px), s.dashed, 1.0});
        svg.text({x + 30.0, y}, s.label, 11.0, "start", "#222222");
        y += 16.0;
    }
}

void draw_series(Svg& svg, const Series& s, const std::vector<Point>& px) {
    if (s.width_px > 0.0) svg.polyline(px, Stroke{s.color, s.width_px, s.dashed, 1.0});
    if (s.markers)
        for (const Point& p : px) svg.circle(p, 2.5, s.color);
}

// Bounding box of the walls and every series of a map panel.
Box data_box(const MapPanel& panel) {
    Box b;
    for (const auto& wall : panel.walls)
        for (const Point& p : wall) b.add(p);
    for (const Series& s : panel.series)
        for (const Point& p : s.points) b.add(p);
    for (const auto& ring : panel.no_go)
        for (const Point& p : ring) b.add(p);
    for (const auto& link : panel.links)
        for (const Point& p : link) b.add(p);
    for (const Marker& m : panel.markers) b.add(m.p);
    return b;
}

const Stroke kLink{"#ff7f0e", 2.0, false, 1.0};

// The map's own drawings beyond walls: shaded no-go rings, connector arrows
// with a head at their last point, labelled landmarks.
template <typename ToPx>
void draw_map_features(Svg& svg, const MapPanel& panel, ToPx to_px) {
    for (const auto& ring : panel.no_go) {
        std::vector<Point> px;
        for (const Point& p : ring) px.push_back(to_px(p));
        if (!px.empty()) px.push_back(px.front());
        svg.polyline(px, Stroke{"#e377c2", 1.0, true, 0.8});
    }
    for (const auto& link : panel.links) {
        std::vector<Point> px;
        for (const Point& p : link) px.push_back(to_px(p));
        svg.polyline(px, kLink);
        if (px.size() < 2) continue;
        const Point &a = px[px.size() - 2], &b = px.back();
        const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
        if (len <= 0.0) continue;
        const double ux = (b[0] - a[0]) / len, uy = (b[1] - a[1]) / len, head = 8.0;
        svg.line(b, {b[0] - head * (ux - 0.5 * uy), b[1] - head * (uy + 0.5 * ux)}, kLink);
        svg.line(b, {b[0] - head * (ux + 0.5 * uy), b[1] - head * (uy - 0.5 * ux)}, kLink);
    }
    for (const Marker& m : panel.markers) {
        const Point c = to_px(m.p);
        svg.rect({c[0] - 3.5, c[1] - 3.5}, 7.0, 7.0, "#9467bd", Stroke{"#9467bd", 0.5, false, 1.0});
        if (!m.label.empty()) svg.text({c[0] + 6.0, c[1] - 5.0}, m.label, 10.0, "start", "#9467bd");
    }
}

void draw_map(Svg& svg, const MapPanel& panel, double ox, double oy, double w, double h) {
    const double ml = 55.0, mr = 15.0, mt = panel.title.empty() ? 12.0 : 30.0, mb = 40.0;
    const double pw = w - ml - mr, ph = h - mt - mb;
    if (!panel.title.empty()) svg.text({ox + w / 2.0, oy + 20.0}, panel.title, 14.0, "middle");
    Box b = data_box(panel);
    if (!b.valid()) b = {0.0, 1.0, 0.0, 1.0};
    const double pad = 0.04 * std::max({b.x1 - b.x0, b.y1 - b.y0, 1.0});
    b.x0 -= pad, b.x1 += pad, b.y0 -= pad, b.y1 += pad;
    // Equal scale on both axes, centred.
    const double scale = std::min(pw / (b.x1 - b.x0), ph / (b.y1 - b.y0));
    const double cx = ox + ml + 0.5 * (pw - scale * (b.x1 - b.x0)),
                 cy = oy + mt + 0.5 * (ph + scale * (b.y1 - b.y0));
    auto to_px = [&](const Point& p) {
        return Point{cx + (p[0] - b.x0) * scale, cy - (p[1] - b.y0) * scale};
    };
    const double left = to_px({b.x0, b.y0})[0], right = to_px({b.x1, b.y0})[0];
    const double bottom = to_px({b.x0, b.y0})[1], top = to_px({b.x0, b.y1})[1];
    for (double t : nice_ticks(b.x0, b.x1, 8)) {
        const double x = to_px({t, b.y0})[0];
        svg.line({x, top}, {x, bottom}, kGrid);
        svg.text({x, bottom + 14.0}, label_of(t), 10.0, "middle", "#444444");
    }
    for (double t : nice_ticks(b.y0, b.y1, 8)) {
        const double y = to_px({b.x0, t})[1];
        svg.line({left, y}, {right, y}, kGrid);
        svg.text({left - 5.0, y + 3.5}, label_of(t), 10.0, "end", "#444444");
    }
    svg.rect({left, top}, right - left, bottom - top, "none", kAxis);
    svg.text({(left + right) / 2.0, bottom + 30.0}, "east (m)", 11.0, "middle", "#444444");
    svg.text({left - 40.0, (top + bottom) / 2.0}, "north (m)", 11.0, "middle", "#444444", -90.0);
    for (const auto& wall : panel.walls) {
        std::vector<Point> px;
        px.reserve(wall.size());
        for (const Point& p : wall) px.push_back(to_px(p));
        svg.polyline(px, kWall);
    }
    draw_map_features(svg, panel, to_px);
    for (const Series& s : panel.series) {
        std::vector<Point> px;
        for (const Point& p : thin(s.points)) px.push_back(to_px(p));
        draw_series(svg, s, px);
        if (!s.points.empty() && s.width_px > 0.0)
            svg.circle(to_px(s.points.front()), 4.0, s.color);  // start
    }
    legend(svg, panel.series, right, top);
}

void draw_time(Svg& svg, const TimePanel& panel, double ox, double oy, double w, double h) {
    const double ml = 55.0, mr = 15.0, mt = panel.title.empty() ? 12.0 : 30.0, mb = 40.0;
    const double pw = w - ml - mr, ph = h - mt - mb;
    if (!panel.title.empty()) svg.text({ox + w / 2.0, oy + 20.0}, panel.title, 14.0, "middle");
    Box b;
    for (const Series& s : panel.series)
        for (const Point& p : s.points) b.add(p);
    if (!b.valid()) b = {0.0, 1.0, 0.0, 1.0};
    b.y0 = std::min(0.0, b.y0);
    b.y1 = std::max(b.y1 * 1.05, b.y0 + 1e-3);
    if (b.x1 <= b.x0) b.x1 = b.x0 + 1.0;
    auto to_px = [&](const Point& p) {
        return Point{ox + ml + (p[0] - b.x0) / (b.x1 - b.x0) * pw,
                     oy + mt + ph - (p[1] - b.y0) / (b.y1 - b.y0) * ph};
    };
    const double left = ox + ml, right = ox + ml + pw, top = oy + mt, bottom = oy + mt + ph;
    for (double t : nice_ticks(b.x0, b.x1, 10)) {
        const double x = to_px({t, 0.0})[0];
        svg.line({x, top}, {x, bottom}, kGrid);
        svg.text({x, bottom + 14.0}, label_of(t), 10.0, "middle", "#444444");
    }
    for (double t : nice_ticks(b.y0, b.y1, 5)) {
        const double y = to_px({b.x0, t})[1];
        svg.line({left, y}, {right, y}, kGrid);
        svg.text({left - 5.0, y + 3.5}, label_of(t), 10.0, "end", "#444444");
    }
    svg.rect({left, top}, pw, ph, "none", kAxis);
    svg.text({(left + right) / 2.0, bottom + 30.0}, "time (s)", 11.0, "middle", "#444444");
    svg.text({left - 40.0, (top + bottom) / 2.0}, panel.y_label, 11.0, "middle", "#444444", -90.0);
    for (const Series& s : panel.series) {
        std::vector<Point> px;
        for (const Point& p : thin(s.points)) px.push_back(to_px(p));
        draw_series(svg, s, px);
    }
    legend(svg, panel.series, right, top);
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target) {
    std::vector<double> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi) || target < 1) return ticks;
    const double raw = (hi - lo) / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) {
            step = m * mag;
            break;
        }
    for (double k = std::ceil(lo / step); k * step <= hi + 1e-9 * step; k += 1.0)
        ticks.push_back(k == 0.0 ? 0.0 : k * step);
    return ticks;
}

std::string render_map(const MapPanel& panel, double width_px, double height_px) {
    Svg svg(width_px, height_px);
    draw_map(svg, panel, 0.0, 0.0, width_px, height_px);
    return svg.str();
}

namespace {

// Height of a map panel of this width: the data's aspect ratio, within limits.
double map_height(const MapPanel& panel, double w) {
    const Box b = data_box(panel);
    double h = 0.66 * w;
    if (b.valid() && b.x1 > b.x0) h = std::clamp((w - 70.0) * (b.y1 - b.y0) / (b.x1 - b.x0) + 80.0, 0.35 * w, 1.1 * w);
    return h;
}

}  // namespace

std::string render_walk(const WalkPlot& plot) {
    const double w = plot.width_px;
    const double map_h = map_height(plot.map, w);
    const bool time = !plot.error.series.empty();
    const double time_h = time ? 0.33 * w : 0.0, title_h = plot.title.empty() ? 0.0 : 30.0;
    Svg svg(w, title_h + map_h + time_h);
    if (!plot.title.empty()) svg.text({w / 2.0, 21.0}, plot.title, 16.0, "middle");
    draw_map(svg, plot.map, 0.0, title_h, w, map_h);
    if (time) draw_time(svg, plot.error, 0.0, title_h + map_h, w, time_h);
    return svg.str();
}

std::string render_map_panels(const std::string& title, const std::vector<MapPanel>& panels, double width_px) {
    const double title_h = title.empty() ? 0.0 : 30.0;
    double h = title_h;
    for (const MapPanel& p : panels) h += map_height(p, width_px);
    Svg svg(width_px, h);
    if (!title.empty()) svg.text({width_px / 2.0, 21.0}, title, 16.0, "middle");
    double y = title_h;
    for (const MapPanel& p : panels) {
        const double ph = map_height(p, width_px);
        draw_map(svg, p, 0.0, y, width_px, ph);
        y += ph;
    }
    return svg.str();
}

}  // namespace pednav::plot
