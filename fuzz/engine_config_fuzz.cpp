// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: pn_engine_create from config JSON text (the config
// parser, the params schemas of every plugin, the pipeline checks, the
// config's map and origin), with every first-party plugin linked in. A
// refused config must come with an error status; a created engine must
// describe itself and take a flush.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "static_plugins.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // NUL-terminated copy: config_len = size also covers embedded NULs.
    const std::string config(reinterpret_cast<const char*>(data), size);
    pn_status_t status = PN_OK;
    pn_engine_t* engine = pednav::fuzz::create_engine(config.c_str(), size, &status);
    if (engine == nullptr) {
        if (!PN_FAILED(status)) __builtin_trap();  // refused without saying so
        return 0;
    }
    size_t needed = 0;
    if (pn_engine_describe(engine, nullptr, 0, &needed) != PN_E_INVALID_ARGUMENT || needed == 0) __builtin_trap();
    std::vector<char> text(needed);
    if (pn_engine_describe(engine, text.data(), text.size(), &needed) != PN_OK) __builtin_trap();
    pn_error_t err{};
    err.struct_size = sizeof err;
    (void)pn_engine_flush(engine, &err);
    pn_engine_destroy(engine);
    return 0;
}
