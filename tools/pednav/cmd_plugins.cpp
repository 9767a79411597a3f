#include "cmd_plugins.hpp"

#include <cstdio>
#include <iostream>

#include "cli_common.hpp"
#include "describe.hpp"
#include "loader.hpp"
#include "params_docs.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav plugins [--json] [--plugin-dir DIR]\n"
    "       pednav plugins --params [--markdown] [--check | --update FILE...] [--plugin-dir DIR]\n"
    "  the plugins found (next to the executable and in each --plugin-dir) and the files rejected;\n"
    "  --params: every plugin's parameters (key, type, unit, range, default, meaning), --markdown as the\n"
    "  README's tables; --check FILE...: the tables between <!-- params:begin --> and <!-- params:end -->\n"
    "  in each FILE agree with the schemas (exit 1 naming each difference); --update FILE...: rewrite\n"
    "  them\n";

}  // namespace

const char* const pednav_cmd_plugins_usage = kUsage;

int pednav_cmd_plugins(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    bool json = false;
    cli::ParamsRequest params_request;
    std::vector<std::string> dirs = {cli::default_plugin_dir()};
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--json") json = true;
        else if (a == "--plugin-dir") dirs.push_back(args.value(a));
        else if (a == "--params") params_request.params = true;
        else if (a == "--markdown") params_request.markdown = true;
        else if (a == "--check") params_request.check = true;
        else if (a == "--update") params_request.update = true;
        else if (a.rfind("-", 0) != 0) params_request.files.push_back(a);
        else throw cli::UsageError("unknown option " + a + " for plugins");
    }
    params_request.plugin_dirs.assign(dirs.begin() + 1, dirs.end());
    engine::Loader loader;
    for (const auto& d : dirs) loader.scan_directory(d);
    const nlohmann::json j = engine::describe_loader(loader);
    if (params_request.asked()) return cli::params_command(j["plugins"], params_request);
    if (json) {
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("%-44s %-19s %-8s %s\n", "plugin", "kind", "version", "mounts");
    for (const auto& p : j["plugins"]) {
        std::string mounts;
        for (const auto& f : p["features"]) {
            const std::string s = f.get<std::string>();
            if (s.rfind("mount:", 0) == 0) mounts += (mounts.empty() ? "" : ",") + s.substr(6);
        }
        std::printf("%-44s %-19s %-8s %s\n", p["id"].get<std::string>().c_str(), p["kind"].get<std::string>().c_str(),
                    p["version"].get<std::string>().c_str(), mounts.empty() ? "any" : mounts.c_str());
    }
    for (const auto& l : j["libraries"]) std::printf("library %s (%s)\n", l["path"].get<std::string>().c_str(), l["id"].get<std::string>().c_str());
    for (const auto& r : j["rejected"])
        std::printf("rejected %s: %s (%s)\n", r["path"].get<std::string>().c_str(), r["reason"].get<std::string>().c_str(),
                    r["status"].get<std::string>().c_str());
    return 0;
}
