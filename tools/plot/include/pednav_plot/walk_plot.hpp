// SPDX-License-Identifier: Apache-2.0
// Plots people would rather look at than read: a walk's estimated track over
// its truth and the map's walls (equal scale on both axes), and its error
// against time, as one SVG document.
#pragma once

#include <string>
#include <vector>

#include <pednav_plot/svg.hpp>

namespace pednav::plot {

struct Series {
    std::string label;
    std::string color = "#1f77b4";
    std::vector<Point> points;  // metres (map) or (time s, value) (time plot)
    double width_px = 1.5;
    bool dashed = false;
    bool markers = false;  // a dot at every point (checkpoints, footprints)
};

// A named point of the map (a landmark, a door).
struct Marker {
    Point p;
    std::string label;
};

struct MapPanel {
    std::string title;
    std::vector<std::vector<Point>> walls;  // metres, drawn grey
    std::vector<Series> series;             // truth first, then estimates
    std::vector<std::vector<Point>> no_go;  // rings where a walker cannot be, shaded
    std::vector<std::vector<Point>> links;  // stairs, escalators, lifts: arrows to their head
    std::vector<Marker> markers;            // landmarks, drawn as labelled squares
};

struct TimePanel {
    std::string title;
    std::string y_label = "horizontal error (m)";
    std::vector<Series> series;
};

struct WalkPlot {
    std::string title;
    MapPanel map;
    TimePanel error;  // empty series: no time panel
    double width_px = 900.0;
};

// The map panel alone, or the whole figure: title, map and (when it has
// series) the time panel below it.
std::string render_map(const MapPanel& panel, double width_px = 900.0, double height_px = 600.0);
std::string render_walk(const WalkPlot& plot);
// Map panels one above the other (one per floor), under a title.
std::string render_map_panels(const std::string& title, const std::vector<MapPanel>& panels, double width_px = 900.0);

// "Nice" tick positions covering [lo, hi] (1, 2, 5 x 10^k steps), about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

}  // namespace pednav::plot
