// The subcommands beyond run and plugins, each in its own file.
#pragma once

#include <string>
#include <vector>

struct PednavSubcommand {
    const char* name;
    int (*run)(const std::vector<std::string>& args);
};

const std::vector<PednavSubcommand>& pednav_subcommands();
