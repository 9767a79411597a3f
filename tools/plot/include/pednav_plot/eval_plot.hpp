// SPDX-License-Identifier: Apache-2.0
// The standard figure of one walk from an evaluation: the track over the
// truth (checkpoints or dense path) and the walls, and the horizontal error
// against time.
#pragma once

#include <string>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/track.hpp>
#include <pednav_eval/truth.hpp>
#include <pednav_plot/floor_plot.hpp>
#include <pednav_plot/walk_plot.hpp>

namespace pednav::plot {

// truth and metrics may be null (a run without truth: the track alone).
// The track is drawn as aligned by metrics->alignment when given.
WalkPlot walk_plot(const std::string& title, const eval::Track& track, const eval::Truth* truth,
                   const eval::Metrics* metrics);

// The same walk over a building map, one panel per floor (floor_plot.hpp):
// truth and track split by the floor of each point (points without one on
// floor 0). truth and metrics may be null.
std::vector<MapPanel> walk_floor_panels(const eval::Track& track, const eval::Truth* truth,
                                        const eval::Metrics* metrics, const indoor_map::Map& map,
                                        const std::vector<std::string>& landmark_names);

}  // namespace pednav::plot
