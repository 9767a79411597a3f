// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <vector>
// pednav plugins [--json] [--plugin-dir DIR]...: what was loaded and rejected;
// --params [--markdown] [--check FILE] [--update FILE]: the plugins' parameters (params_docs.hpp).
int pednav_cmd_plugins(const std::vector<std::string>& args);
// Its usage text (pednav plugins --help).
extern const char* const pednav_cmd_plugins_usage;
