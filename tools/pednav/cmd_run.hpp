// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <vector>
// pednav run --mount foot|chest|waist [--config FILE] --input FILE [--format NAME]
//   [--output track.csv] [--steps FILE] [--start x,y,z] [--heading DEG]
//   [--geojson FILE] [--gpx FILE] [--summary FILE] [--plot FILE.svg] [--plugin-dir DIR]...
//   [--column-map FILE.json] [--origin lat,lon,height]
int pednav_cmd_run(const std::vector<std::string>& args);
// Its usage text (pednav run --help).
extern const char* const pednav_cmd_run_usage;
