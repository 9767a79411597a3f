// SPDX-License-Identifier: Apache-2.0
// pednav: the command-line front end of the engine.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>

#include "cli_common.hpp"
#include "subcommands.hpp"
#include "supervise.hpp"

namespace {

void print_usage(FILE* out) {
    std::fputs("usage: pednav <command> [options]   (pednav <command> --help: that command's options;\n"
               "       pednav --version: the engine and C ABI versions)\n", out);
    for (const auto& c : pednav_subcommands()) std::fprintf(out, "  %-8s %s\n", c.name, c.summary);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        print_usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (!std::strcmp(argv[1], "--version") || !std::strcmp(argv[1], "version")) {
        const uint32_t abi = pn_abi_version();
        std::printf("pednav %s (C ABI %u.%u)\n", pn_version_string(), PN_ABI_VERSION_MAJOR(abi), PN_ABI_VERSION_MINOR(abi));
        return 0;
    }
    const std::string command = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    for (const auto& c : pednav_subcommands()) {
        if (command != c.name) continue;
        auto run = [&]() -> int {
            try {
                return c.run(args);
            } catch (const pednav::cli::HelpRequested& e) {
                std::fputs(e.what(), stdout);
                return 0;
            } catch (const pednav::cli::UsageError& e) {
                std::fprintf(stderr, "pednav %s: %s\n%s", c.name, e.what(), c.usage);
                return 2;
            } catch (const std::exception& e) {
                std::fprintf(stderr, "pednav %s: %s\n", c.name, e.what());
                return 1;
            }
        };
        // `run` drives plugins over a whole recording: a plugin ending the
        // process (abort, segfault, _exit(0)) must not pass for a clean run.
        if (command == "run") return pednav::cli::run_supervised(c.name, run);
        return run();
    }
    std::fprintf(stderr, "pednav: unknown command \"%s\"\n", command.c_str());
    print_usage(stderr);
    return 2;
}
