// SPDX-License-Identifier: Apache-2.0
// pednav map: check a pednav.map/1 map, convert floor plans to one
// (docs/maps.md).
#pragma once

#include <string>
#include <vector>

// args exclude the word "map". Returns the process exit status.
int pednav_cmd_map(const std::vector<std::string>& args);
// Its usage text (pednav map --help).
extern const char* const pednav_cmd_map_usage;
