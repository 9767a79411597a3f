// SPDX-License-Identifier: Apache-2.0
// Every first-party plugin library linked in (PEDNAV_BUILD_STATIC), handed to
// pn_engine_create as static libraries: engines of every preset without
// dlopen, so each fuzz input creates its engine cheaply and the same way.
#pragma once

#include <cstdint>

#include <pednav/pn_engine.h>

namespace pednav::fuzz {

const pnp_library_t* const* static_plugin_libraries(uint32_t* count);

// An engine from config JSON text (size bytes) with the linked-in plugins; NULL
// when pn_engine_create refuses it (its status in *status).
pn_engine_t* create_engine(const char* config_json, size_t size, pn_status_t* status);

}  // namespace pednav::fuzz
