// SPDX-License-Identifier: Apache-2.0
// JSON description of what a Loader found (libraries, plugins, rejected files,
// load warnings), and of one plugin descriptor.
#pragma once

#include <nlohmann/json.hpp>

#include "loader.hpp"

namespace pednav::engine {
// The "libraries", "plugins", "rejected" and "load_warnings" members of pn_engine_describe.
nlohmann::json describe_loader(const Loader& loader);
// One plugin as "plugins" lists it, without its "library" (also a manifest's plugin entry).
nlohmann::json describe_plugin(const pnp_descriptor_t* descriptor);
}
