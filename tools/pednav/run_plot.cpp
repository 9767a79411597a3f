// SPDX-License-Identifier: Apache-2.0
#include "run_plot.hpp"

#include <pednav_eval/track.hpp>
#include <pednav_plot/eval_plot.hpp>
#include <pednav_plot/svg.hpp>

namespace pednav::cli {

void write_run_plot(const std::string& svg_path, const std::string& title, const ReplayResult& result) {
    const eval::Track track = eval::track_from_positions(result.positions);
    plot::write_text_file(svg_path, plot::render_walk(plot::walk_plot(title, track, nullptr, nullptr)));
}

}  // namespace pednav::cli
