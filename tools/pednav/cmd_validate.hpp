// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <string>
#include <vector>
// pednav validate LIB.so [--plugin ID] [--mount M] [--json] [--timeout S] [--plugin-dir DIR]...:
// the conformance checks of pednav_validate/validate.hpp on one plugin library.
// Exit 0 when every check passes, 1 when one fails, 2 on a usage error.
int pednav_cmd_validate(const std::vector<std::string>& args);
extern const char* const pednav_cmd_validate_usage;
