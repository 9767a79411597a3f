// pednav: the command-line front end of the engine.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "cmd_plugins.hpp"
#include "cmd_run.hpp"
#include "subcommands.hpp"

namespace {

const char* kUsage =
    "usage: pednav <command> [options]         (pednav <command> --help: that command's usage)\n"
    "  demo [--out DIR] [--route NAME] [--seed N] [--rate HZ]\n"
    "                                   simulate a foot walk, run the foot pipeline, print its error, plot it\n"
    "  run --mount foot|chest|waist --input FILE [--config FILE] [--format NAME] [--output track.csv]\n"
    "      [--steps FILE] [--start x,y,z] [--heading DEG] [--geojson FILE] [--gpx FILE]\n"
    "      [--summary FILE] [--plot FILE.svg] [--column-map FILE.json] [--origin lat,lon,height]\n"
    "  plugins [--json]                 plugins loaded and files rejected\n"
    "  inspect FILE [--json] [--format NAME] [--column-map FILE.json] [--gap S]\n"
    "                                   what the engine sees in a recording\n"
    "  sim --route FILE|NAME --out DIR [--mount foot|chest|waist] [--rate HZ] [--seed N] ...\n"
    "  eval --track FILE --truth PATH [--kind KIND] [--align MODE] [--json] ...\n"
    "  report --out DIR ...             accuracy of every recording and simulated walk\n"
    "demo, run, plugins and report also take --plugin-dir DIR (adds a plugin directory)\n";

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        std::fputs(kUsage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    try {
        if (command == "run") return pednav_cmd_run(args);
        if (command == "plugins") return pednav_cmd_plugins(args);
        for (const auto& sub : pednav_subcommands())
            if (command == sub.name) return sub.run(args);
        std::fprintf(stderr, "pednav: unknown command \"%s\"\n%s", command.c_str(), kUsage);
        return 2;
    } catch (const pednav::cli::HelpRequested& e) {
        std::fputs(e.what(), stdout);
        return 0;
    } catch (const pednav::cli::UsageError& e) {
        std::fprintf(stderr, "pednav %s: %s\n%s", command.c_str(), e.what(), kUsage);
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pednav %s: %s\n", command.c_str(), e.what());
        return 1;
    }
}
