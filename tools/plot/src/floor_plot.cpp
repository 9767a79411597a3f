// SPDX-License-Identifier: Apache-2.0
#include <pednav_plot/floor_plot.hpp>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

namespace pednav::plot {

namespace {

Point point_of(const indoor_map::Point2& p) { return {p.e_m, p.n_m}; }

std::vector<Point> points_of(const std::vector<indoor_map::Point2>& ps) {
    std::vector<Point> out;
    out.reserve(ps.size());
    for (const auto& p : ps) out.push_back(point_of(p));
    return out;
}

int floor_at(const FloorSeries& s, size_t i) { return i < s.floors.size() ? s.floors[i] : 0; }

// The series' points on `floor`; a point elsewhere breaks the line.
Series on_floor(const FloorSeries& s, int floor) {
    Series out = s.series;
    out.points.clear();
    const Point gap{NAN, NAN};
    for (size_t i = 0; i < s.series.points.size(); ++i) {
        if (floor_at(s, i) == floor) out.points.push_back(s.series.points[i]);
        else if (!out.points.empty() && std::isfinite(out.points.back()[0]) && s.series.width_px > 0.0)
            out.points.push_back(gap);
    }
    while (!out.points.empty() && !std::isfinite(out.points.back()[0])) out.points.pop_back();
    return out;
}

}  // namespace

std::vector<MapPanel> floor_panels(const indoor_map::Map& map, const std::vector<std::string>& names,
                                   const std::vector<FloorSeries>& series) {
    std::vector<int> floors = map.floors;
    for (const FloorSeries& s : series)
        for (size_t i = 0; i < s.series.points.size(); ++i) floors.push_back(floor_at(s, i));
    std::sort(floors.begin(), floors.end());
    floors.erase(std::unique(floors.begin(), floors.end()), floors.end());
    std::vector<MapPanel> panels;
    for (int f : floors) {
        MapPanel p;
        p.title = "floor " + std::to_string(f);
        for (const auto& w : map.walls)
            if (w.floor == f) p.walls.push_back({point_of(w.a), point_of(w.b)});
        for (const auto& z : map.zones)
            if (z.floor == f && z.kind == indoor_map::ZoneKind::no_particles) p.no_go.push_back(points_of(z.rings[0]));
        // A connector shows on both floors it joins: an arrow from its foot
        // to its head, an area as its outline closed back to the start.
        for (const auto& c : map.connectors) {
            if (c.floor != f && c.floor_to != f) continue;
            std::vector<Point> line = points_of(c.area);
            if (!c.is_arrow && !line.empty()) line.push_back(line.front());
            p.links.push_back(std::move(line));
        }
        for (size_t k = 0; k < map.landmarks.size(); ++k)
            if (map.landmarks[k].floor == f)
                p.markers.push_back({point_of(map.landmarks[k].p), k < names.size() ? names[k] : std::string()});
        for (const FloorSeries& s : series) {
            Series part = on_floor(s, f);
            if (!part.points.empty()) p.series.push_back(std::move(part));
        }
        panels.push_back(std::move(p));
    }
    return panels;
}

std::vector<std::string> landmark_names(std::string_view map_document, const indoor_map::Map& map) {
    std::vector<std::string> names;
    const nlohmann::json doc = nlohmann::json::parse(map_document.begin(), map_document.end(), nullptr, false);
    if (doc.is_discarded() || !doc.contains("features") || !doc["features"].is_array()) return names;
    for (const auto& l : map.landmarks) {
        std::string name;
        if (l.feature >= 0 && static_cast<size_t>(l.feature) < doc["features"].size()) {
            const auto& props = doc["features"][static_cast<size_t>(l.feature)].value("properties", nlohmann::json::object());
            if (props.is_object()) {
                if (props.contains("pednav:name") && props["pednav:name"].is_string()) name = props["pednav:name"];
                else if (props.contains("name") && props["name"].is_string()) name = props["name"];
            }
        }
        names.push_back(name);
    }
    return names;
}

}  // namespace pednav::plot
