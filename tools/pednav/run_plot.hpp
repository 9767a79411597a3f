// SPDX-License-Identifier: Apache-2.0
// `pednav run --plot FILE.svg`: the track of one run as SVG.
#pragma once

#include <string>

#include <pednav_engine/replay.hpp>

namespace pednav::cli {
void write_run_plot(const std::string& svg_path, const std::string& title, const ReplayResult& result);
}
