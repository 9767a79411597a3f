// SPDX-License-Identifier: Apache-2.0
// A mount preset (configs/<mount>.json) with a JSON merge patch applied: how
// pednav report --patch and the accuracy tests try a parameter or a plugin
// without editing the preset.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace pednav::eval {

// `preset_json` (a pednav-config/1 document) with `patch` merged in (RFC 7386),
// as config text for the engine. A stage whose plugin the patch replaces starts
// from the new plugin's own defaults: the preset's params of that stage are
// dropped before the patch is merged. Throws std::runtime_error when the preset
// is not JSON or the patch is not a JSON object.
std::string patched_config(const std::string& preset_json, const nlohmann::json& patch);

// `config_json` with the walker's height given to every position filter that
// takes one (its params list `user_height_m`, as a preset lists every
// parameter): what an app that knows its user does. A height <= 0 (unknown)
// leaves the config as it is.
std::string with_user_height(const std::string& config_json, double height_m);

}  // namespace pednav::eval
