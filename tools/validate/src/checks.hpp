// SPDX-License-Identifier: Apache-2.0
// The bodies of the checks, each run inside a child process by validate.cpp.
// Each returns {"passed": bool, "reason": text, "detail": {...}}.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_types.h>

#include "pednav_validate/validate.hpp"

namespace pednav::validate {

nlohmann::json check_result(bool passed, const std::string& reason, nlohmann::json detail = nlohmann::json::object());

// "load": opens the library with the engine's loader. detail.plugins lists
// each accepted plugin as the manifest does (id, kind, mounts, params_schema).
nlohmann::json load_check(const std::string& library_path);
// "manifest": the manifest beside the library agrees with its descriptors.
nlohmann::json manifest_check(const std::string& library_path);

// Where a plugin is put to test it: a mount's preset with the plugin in its role.
struct Placement {
    std::string library_path;
    std::string plugin_id;
    std::string role;         // the kind's name, which is also its stage's key
    std::string mount;
    nlohmann::json config;    // the whole engine config
    nlohmann::json params_schema;  // the plugin's, or null
    std::vector<std::string> plugin_dirs;  // the library's own directory first
    const std::vector<const pn_record_header_t*>* records = nullptr;  // the simulated walk
    std::string pointer() const { return "/pipelines/" + mount + "/" + role; }
};

nlohmann::json lifecycle_check(const Placement& p);
nlohmann::json outputs_check(const Placement& p);
nlohmann::json reset_check(const Placement& p);
nlohmann::json determinism_check(const Placement& p);
nlohmann::json logging_check(const Placement& p);
nlohmann::json params_check(const Placement& p);

}  // namespace pednav::validate
