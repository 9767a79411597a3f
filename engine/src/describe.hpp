// SPDX-License-Identifier: Apache-2.0
// JSON description of what a Loader found (libraries, plugins, rejected files,
// load warnings), and of one plugin descriptor.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "loader.hpp"

namespace pednav::engine {
// The "libraries", "plugins", "rejected" and "load_warnings" members of pn_engine_describe.
nlohmann::json describe_loader(const Loader& loader);
// One plugin as "plugins" lists it, without its "library" (also a manifest's plugin entry).
nlohmann::json describe_plugin(const pnp_descriptor_t* descriptor);

// The two-call size idiom of the describe functions: *size = text + NUL; the
// text into buffer when it fits (PN_OK), else an empty buffer and
// PN_E_INVALID_ARGUMENT, so the caller calls again with *size.
pn_status_t copy_text_out(const std::string& text, char* buffer, size_t capacity, size_t* size);
}
