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

struct MapPanel {
    std::string title;
    std::vector<std::vector<Point>> walls;  // metres, drawn grey
    std::vector<Series> series;             // truth first, then estimates
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

// "Nice" tick positions covering [lo, hi] (1, 2, 5 x 10^k steps), about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target = 6);

}  // namespace pednav::plot
