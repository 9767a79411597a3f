// SPDX-License-Identifier: Apache-2.0
// The standard figure of one walk from an evaluation: the track over the
// truth (checkpoints or dense path) and the walls, and the horizontal error
// against time.
#pragma once

#include <string>

#include <pednav_eval/metrics.hpp>
#include <pednav_eval/track.hpp>
#include <pednav_eval/truth.hpp>
#include <pednav_plot/walk_plot.hpp>

namespace pednav::plot {

// truth and metrics may be null (a run without truth: the track alone).
// The track is drawn as aligned by metrics->alignment when given.
WalkPlot walk_plot(const std::string& title, const eval::Track& track, const eval::Truth* truth,
                   const eval::Metrics* metrics);

}  // namespace pednav::plot
