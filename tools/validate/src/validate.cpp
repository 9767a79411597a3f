// SPDX-License-Identifier: Apache-2.0
// Runs the checks of validate.hpp, each in its own child process.
#include "pednav_validate/validate.hpp"

#include <climits>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <pednav_sim/simulate.hpp>

#include "checks.hpp"
#include "pednav_validate/isolated.hpp"

namespace pednav::validate {

bool Report::passed() const {
    for (const auto& c : checks)
        if (!c.passed) return false;
    return !checks.empty();
}

const CheckResult* Report::failed(const std::string& check, const std::string& plugin) const {
    for (const auto& c : checks)
        if (!c.passed && c.check == check && (plugin.empty() || c.plugin == plugin)) return &c;
    return nullptr;
}

nlohmann::json to_json(const Report& report) {
    nlohmann::json checks = nlohmann::json::array();
    size_t failed = 0;
    for (const auto& c : report.checks) {
        checks.push_back({{"check", c.check},
                          {"plugin", c.plugin},
                          {"mount", c.mount},
                          {"passed", c.passed},
                          {"reason", c.reason},
                          {"detail", c.detail}});
        failed += c.passed ? 0 : 1;
    }
    return {{"library", report.library},
            {"passed", report.passed()},
            {"checks_run", report.checks.size()},
            {"checks_failed", failed},
            {"checks", checks}};
}

namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    if (!in) return {};
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string directory_of(const std::string& path) {
    char resolved[PATH_MAX];
    const std::string real = realpath(path.c_str(), resolved) ? std::string(resolved) : path;
    const size_t slash = real.find_last_of('/');
    return slash == std::string::npos ? "." : real.substr(0, slash);
}

CheckResult to_check(const std::string& check, const std::string& plugin, const std::string& mount,
                     const IsolatedResult& r) {
    CheckResult c;
    c.check = check;
    c.plugin = plugin;
    c.mount = mount;
    if (!r.finished) {
        c.reason = r.failure;
    } else if (r.result.contains("exception")) {
        c.reason = "the check threw: " + r.result["exception"].get<std::string>();
    } else {
        c.passed = r.result.value("passed", false);
        c.reason = r.result.value("reason", std::string());
        c.detail = r.result.value("detail", nlohmann::json::object());
    }
    return c;
}

using CheckFn = nlohmann::json (*)(const Placement&);
const std::vector<std::pair<const char*, CheckFn>>& plugin_checks() {
    static const std::vector<std::pair<const char*, CheckFn>> table = {
        {"lifecycle", &lifecycle_check}, {"outputs", &outputs_check}, {"reset", &reset_check},
        {"determinism", &determinism_check}, {"params", &params_check}, {"logging", &logging_check}};
    return table;
}

}  // namespace

Report validate_library(const std::string& library_path, const Options& options, const CheckCallback& on_check) {
    Report report;
    report.library = library_path;
    auto add = [&](CheckResult c) -> const CheckResult& {
        report.checks.push_back(std::move(c));
        if (on_check) on_check(report.checks.back());
        return report.checks.back();
    };
    const CheckResult load =
        add(to_check("load", "", "", run_isolated([&] { return load_check(library_path); }, options.timeout_s)));
    add(to_check("manifest", "", "", run_isolated([&] { return manifest_check(library_path); }, options.timeout_s)));
    if (!load.passed) return report;
    const nlohmann::json plugins = load.detail.value("plugins", nlohmann::json::array());

    std::vector<std::string> dirs = {directory_of(library_path)};
    for (const auto& d : options.plugin_dirs)
        if (directory_of(d + "/.") != dirs.front()) dirs.push_back(d);

    bool found = options.plugin_id.empty();
    std::map<std::string, pednav::sim::SimOutput> walks;  // simulated here, before any fork: the children share it
    for (const auto& plugin : plugins) {
        const std::string id = plugin.value("id", "");
        if (!options.plugin_id.empty() && id != options.plugin_id) continue;
        found = true;
        std::vector<std::string> mounts;
        for (const auto& m : plugin.value("mounts", nlohmann::json::array())) mounts.push_back(m.get<std::string>());
        if (mounts.empty()) mounts = {"foot", "chest", "handheld", "waist"};
        const std::string role = plugin.value("kind", "unknown");
        for (const auto& mount : mounts) {
            if (!options.mount.empty() && mount != options.mount) continue;
            const std::string preset_path = options.config_dir + "/" + mount + ".json";
            const std::string preset_text = read_text(preset_path);
            if (preset_text.empty()) {
                CheckResult c{"placement", id, mount, false,
                              "declares mount:" + mount + " but there is no preset " + preset_path, nlohmann::json::object()};
                add(std::move(c));
                continue;
            }
            Placement p;
            p.library_path = library_path;
            p.plugin_id = id;
            p.role = role;
            p.mount = mount;
            p.params_schema = plugin.value("params_schema", nlohmann::json());
            p.plugin_dirs = dirs;
            p.config = nlohmann::json::parse(preset_text);
            p.config["mount"] = mount;
            nlohmann::json& stage = p.config["pipelines"][mount][role];
            if (!stage.is_object() || stage.value("plugin", "") != id)
                stage = {{"plugin", id}, {"params", nlohmann::json::object()}};
            auto walk = walks.find(mount);
            if (walk == walks.end()) {
                pednav::sim::SimOptions so;
                so.mount = mount;
                so.rate_hz = options.rate_hz;
                so.seed = options.seed;
                walk = walks.emplace(mount, pednav::sim::simulate(pednav::sim::builtin_route(options.route), so)).first;
            }
            const auto records = walk->second.records();
            p.records = &records;
            for (const auto& [name, fn] : plugin_checks()) {
                const CheckFn f = fn;
                add(to_check(name, id, mount, run_isolated([&] { return f(p); }, options.timeout_s)));
            }
        }
    }
    if (!found) {
        std::string ids;
        for (const auto& plugin : plugins) ids += (ids.empty() ? "" : ", ") + plugin.value("id", std::string());
        add({"placement", options.plugin_id, "", false, "the library has no plugin " + options.plugin_id + " (it has " + ids + ")", nlohmann::json::object()});
    }
    return report;
}

}  // namespace pednav::validate
