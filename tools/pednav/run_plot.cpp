// SPDX-License-Identifier: Apache-2.0
#include "run_plot.hpp"

#include "cli_common.hpp"

#include <pednav_eval/track.hpp>
#include <pednav_indoor_map/geojson_map.hpp>
#include <pednav_plot/eval_plot.hpp>
#include <pednav_plot/svg.hpp>

namespace pednav::cli {

void write_run_plot(const std::string& svg_path, const std::string& title, const ReplayResult& result,
                    const std::string& map_path, const std::optional<geodesy::GeodeticPoint>& origin) {
    const eval::Track track = eval::track_from_positions(result.positions);
    if (map_path.empty()) {
        plot::write_text_file(svg_path, plot::render_walk(plot::walk_plot(title, track, nullptr, nullptr)));
        return;
    }
    const std::string doc = read_text_file(map_path);
    const indoor_map::Map map = indoor_map::read_geojson_map(doc, origin);
    plot::write_text_file(svg_path, plot::render_map_panels(title, plot::walk_floor_panels(track, nullptr, nullptr, map,
                                                                                           plot::landmark_names(doc, map))));
}

}  // namespace pednav::cli
