// SPDX-License-Identifier: Apache-2.0
// The engine's check of a stage's params against its plugin's params schema
// (pnp_descriptor_t::params_schema_json, the subset of
// pednav_sdk/params_schema.hpp), run before the plugin's create: a config the
// schema refuses never reaches the plugin. Cross-field rules stay in the
// plugins.
#pragma once

#include <pednav/pn_plugin.h>

#include "config.hpp"

namespace pednav::engine {

// Throws ConfigProblem:
//  - PN_E_INVALID_CONFIG at <stage>/params/<key> for an unknown key, a value
//    of the wrong type, out of range or not in the enum, with a message
//    naming key, value and range ("window_s is 5, outside [0, 2] s");
//  - PN_E_INTERNAL at <stage>/plugin when the schema is not valid JSON or
//    uses keywords outside the subset (the plugin is broken, not the config).
// A plugin without a schema is not checked here (it checks its params itself).
// A key whose value is null counts as absent, as in the SDK: the default applies.
void check_params_against_schema(const pnp_descriptor_t& plugin, const StageConfig& stage);

}  // namespace pednav::engine
