// SPDX-License-Identifier: Apache-2.0
#include "cmd_plugins.hpp"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <pednav/pn_engine.h>
#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "params_docs.hpp"

namespace {

constexpr const char* kUsage =
    "usage: pednav plugins [--json] [--no-open] [--plugin-dir DIR]\n"
    "       pednav plugins --params [--markdown] [--check | --update FILE...] [--plugin-dir DIR]\n"
    "  the plugins found (next to the executable and in each --plugin-dir), the files rejected and\n"
    "  the libraries without a manifest; every library is opened to check it against its manifest,\n"
    "  --no-open reads the manifests only;\n"
    "  --params: every plugin's parameters (key, type, unit, range, default, meaning), --markdown as the\n"
    "  README's tables; --check FILE...: the tables between <!-- params:begin --> and <!-- params:end -->\n"
    "  in each FILE agree with the schemas (exit 1 naming each difference); --update FILE...: rewrite\n"
    "  them\n";

// pn_plugins_describe, parsed.
nlohmann::json describe_plugins(const std::vector<std::string>& dirs, uint32_t flags) {
    std::vector<const char*> dir_ptrs;
    for (const auto& d : dirs) dir_ptrs.push_back(d.c_str());
    pn_error_t err{};
    err.struct_size = sizeof err;
    const uint32_t count = static_cast<uint32_t>(dir_ptrs.size());
    size_t size = 0;
    pn_status_t st = pn_plugins_describe(dir_ptrs.data(), count, flags, nullptr, 0, &size, &err);
    std::string text;
    // Again if a directory changed between two calls and the text grew.
    for (int attempt = 0; attempt < 3 && st == PN_E_INVALID_ARGUMENT && size > text.size(); ++attempt) {
        text.assign(size, '\0');
        st = pn_plugins_describe(dir_ptrs.data(), count, flags, &text[0], text.size(), &size, &err);
    }
    if (st != PN_OK) throw std::runtime_error(std::string("listing plugins failed: ") + err.message);
    text.resize(size - 1);
    return nlohmann::json::parse(text);
}

}  // namespace

const char* const pednav_cmd_plugins_usage = kUsage;

int pednav_cmd_plugins(const std::vector<std::string>& argv) {
    using namespace pednav;
    cli::Args args(argv, kUsage);
    bool json = false;
    uint32_t flags = PN_LIST_OPEN_LIBRARIES;
    cli::ParamsRequest params_request;
    std::vector<std::string> dirs = {cli::default_plugin_dir()};
    while (!args.done()) {
        const std::string a = args.next();
        if (a == "--json") json = true;
        else if (a == "--no-open") flags = 0;
        else if (a == "--plugin-dir") dirs.push_back(args.value(a));
        else if (a == "--params") params_request.params = true;
        else if (a == "--markdown") params_request.markdown = true;
        else if (a == "--check") params_request.check = true;
        else if (a == "--update") params_request.update = true;
        else if (a.rfind("-", 0) != 0) params_request.files.push_back(a);
        else throw cli::UsageError("unknown option " + a + " for plugins");
    }
    params_request.plugin_dirs.assign(dirs.begin() + 1, dirs.end());
    const nlohmann::json j = describe_plugins(dirs, flags);
    if (params_request.asked()) return cli::params_command(j["plugins"], params_request);
    if (json) {
        std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        return 0;
    }
    std::printf("%-44s %-19s %-8s %s\n", "plugin", "kind", "version", "mounts");
    for (const auto& p : j["plugins"]) {
        std::string mounts;
        for (const auto& m : p["mounts"]) mounts += (mounts.empty() ? "" : ",") + m.get<std::string>();
        std::printf("%-44s %-19s %-8s %s\n", p["id"].get<std::string>().c_str(),
                    p["kind"].get<std::string>().c_str(), p["version"].get<std::string>().c_str(),
                    mounts.empty() ? "any" : mounts.c_str());
    }
    for (const auto& l : j["libraries"])
        std::printf("library %s (%s)%s\n", l["path"].get<std::string>().c_str(),
                    l["id"].get<std::string>().c_str(), l["manifest"].is_null() ? ", no manifest" : "");
    for (const auto& r : j["rejected"])
        std::printf("rejected %s: %s (%s)\n", r["path"].get<std::string>().c_str(),
                    r["reason"].get<std::string>().c_str(), r["status"].get<std::string>().c_str());
    for (const auto& w : j["load_warnings"])
        std::printf("warning %s: %s\n", w["path"].get<std::string>().c_str(),
                    w["warning"].get<std::string>().c_str());
    return 0;
}
