// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <vector>
// pednav inspect FILE [--json] [--format NAME] [--column-map FILE] [--gap S]:
// what the engine sees in a recording before anything runs.
int pednav_cmd_inspect(const std::vector<std::string>& args);
// Its usage text (pednav inspect --help).
extern const char* const pednav_cmd_inspect_usage;
