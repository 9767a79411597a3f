// SPDX-License-Identifier: Apache-2.0
// pn_plugins_describe: what the plugin directories offer, with no config and
// no engine. No exception leaves this file.
#include <new>
#include <string>

#include <pednav/pn_engine.h>

#include "describe.hpp"
#include "engine.hpp"
#include "loader.hpp"

using pednav::engine::Loader;
using pednav::engine::set_error;

extern "C" {

pn_status_t pn_plugins_describe(const char* const* plugin_dirs, uint32_t dir_count, uint32_t flags,
                                char* buffer, size_t capacity, size_t* size, pn_error_t* err) {
    if (dir_count && !plugin_dirs) {
        set_error(err, PN_E_INVALID_ARGUMENT, "plugin_dirs",
                  "plugin_dirs is NULL but dir_count is " + std::to_string(dir_count));
        return PN_E_INVALID_ARGUMENT;
    }
    if (flags & ~PN_LIST_OPEN_LIBRARIES) {
        set_error(err, PN_E_INVALID_ARGUMENT, "flags",
                  "unknown flag bits " + std::to_string(flags & ~PN_LIST_OPEN_LIBRARIES) +
                      " (only PN_LIST_OPEN_LIBRARIES is defined)");
        return PN_E_INVALID_ARGUMENT;
    }
    std::string text;
    try {
        Loader loader;
        for (uint32_t i = 0; i < dir_count; ++i)
            if (plugin_dirs[i]) loader.scan_directory(plugin_dirs[i]);
        if (flags & PN_LIST_OPEN_LIBRARIES) loader.open_all();
        text = pednav::engine::describe_loader(loader).dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
    } catch (const std::bad_alloc&) {
        set_error(err, PN_E_OUT_OF_MEMORY, "plugins_describe", "out of memory");
        return PN_E_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        set_error(err, PN_E_INTERNAL, "plugins_describe", e.what());
        return PN_E_INTERNAL;
    }
    const pn_status_t st = pednav::engine::copy_text_out(text, buffer, capacity, size);
    if (st != PN_OK)
        set_error(err, st, "buffer",
                  "the description needs " + std::to_string(text.size() + 1) + " bytes, capacity is " +
                      std::to_string(buffer ? capacity : 0));
    return st;
}

}  // extern "C"
