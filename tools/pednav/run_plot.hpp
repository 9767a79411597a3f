// SPDX-License-Identifier: Apache-2.0
// `pednav run --plot FILE.svg`: the track of one run as SVG.
#pragma once

#include <optional>
#include <string>

#include <pednav_geodesy/enu.hpp>

#include <pednav_engine/replay.hpp>

namespace pednav::cli {
// With a map (a pednav.map/1 document, read around `origin` or its own), the
// track over it, one panel per floor.
void write_run_plot(const std::string& svg_path, const std::string& title, const ReplayResult& result,
                    const std::string& map_path = "", const std::optional<geodesy::GeodeticPoint>& origin = std::nullopt);
}
