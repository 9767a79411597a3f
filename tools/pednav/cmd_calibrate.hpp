// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <vector>
// pednav calibrate --mount M --config CFG --input WALK --distance-m D [--input WALK --distance-m D ...]
// [--input WALK --landmarks FILE] --out NEW_CFG: runs each walk through the
// pipeline, fits the position filter's step constants (pednav_eval/calibration.hpp)
// and writes a copy of the config with them.
int pednav_cmd_calibrate(const std::vector<std::string>& args);
extern const char* const pednav_cmd_calibrate_usage;
