// SPDX-License-Identifier: Apache-2.0
// The conformance checks every plugin library must pass, shared by
// `pednav validate` and the conformance tests (docs/writing-a-plugin.md).
//
// Library checks: "load" (the loader accepts it: entry symbol, ABI major,
// struct sizes, descriptors) and "manifest" (the manifest beside it matches
// its descriptors). Then, for each plugin and each mount it declares (all four
// when it declares none), the plugin is put into its role in that mount's
// preset pipeline and the pipeline is run through the C API on a simulated
// walk of that mount (IMU, magnetometer, barometer, GNSS; the other stages
// supply steps, attitudes and positions):
//   lifecycle    create, process, flush, reset, process, flush, destroy succeed
//   outputs      time-ordered, finite, unit quaternions, symmetric PSD
//                covariances, no contract violation caught by the engine's sink
//   reset        the same input after reset gives the same output bytes
//   determinism  a second engine on the same input gives the same bytes
//   params       defaults alone are valid; an unknown key, a value of the wrong
//                type and one out of range (derived from the params schema) are
//                each refused with PN_E_INVALID_CONFIG naming the key
//   logging      lines logged from create, process, flush, reset and destroy
//                reach the app's log callback, attributed to the instance
// Every check runs in its own child process with a timeout: a crash, abort,
// hang or _exit fails that check with the signal or status.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pednav::validate {

struct Options {
    std::vector<std::string> plugin_dirs;  // where the other stages' plugins are (first-party)
    std::string config_dir;                // the mount presets (<mount>.json)
    std::string plugin_id;                 // only this plugin of the library; empty = all
    std::string mount;                     // only this mount; empty = the plugin's own
    double timeout_s = 60;                 // per check
    std::string route = "corridor_loop";   // simulated walk (pednav sim --list-routes)
    double rate_hz = 200;
    uint64_t seed = 11;
};

struct CheckResult;
// Called as each check ends (progress display); may be empty.
using CheckCallback = std::function<void(const CheckResult&)>;

struct CheckResult {
    std::string check;   // "load", "manifest", "lifecycle", ...
    std::string plugin;  // empty for the library checks
    std::string mount;
    bool passed = false;
    std::string reason;  // why it failed; empty when it passed
    nlohmann::json detail = nlohmann::json::object();  // what was measured
};

struct Report {
    std::string library;  // the path given
    std::vector<CheckResult> checks;
    bool passed() const;
    // The first failed check of that name (and plugin, when not empty), or NULL.
    const CheckResult* failed(const std::string& check, const std::string& plugin = {}) const;
};

// Throws std::runtime_error only when the validator itself cannot work (no
// preset for a mount, fork failing); everything the library does is a check.
Report validate_library(const std::string& library_path, const Options& options,
                        const CheckCallback& on_check = {});

nlohmann::json to_json(const Report& report);

}  // namespace pednav::validate
