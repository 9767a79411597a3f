// SPDX-License-Identifier: Apache-2.0
// Every pednav command: its name, its entry point and its usage text.
#pragma once

#include <string>
#include <vector>

struct PednavSubcommand {
    const char* name;
    int (*run)(const std::vector<std::string>& args);  // args exclude the command's name
    const char* usage;
    const char* summary;  // one line for pednav's own usage
};

const std::vector<PednavSubcommand>& pednav_subcommands();
