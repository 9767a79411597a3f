// SPDX-License-Identifier: Apache-2.0
// pednav sim: simulate a walk along a route and write the engine input, the
// truth, GNSS fixes and the building map (see docs/simulator.md).
#pragma once

#include <string>
#include <vector>

// args exclude the word "sim". Returns the process exit status.
int pednav_cmd_sim(const std::vector<std::string>& args);
// Its usage text (pednav sim --help).
extern const char* const pednav_cmd_sim_usage;
