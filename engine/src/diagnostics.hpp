// SPDX-License-Identifier: Apache-2.0
// What the engine tells the app about itself: log lines to the app's callback
// and the warnings kept for pn_engine_describe. It is the first thing an
// Engine builds, so a plugin may log from its library's init and from create,
// before any pipeline exists. Nothing here throws: a warning that cannot be
// stored for lack of memory is still counted.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>

#include "origin.hpp"

namespace pednav::engine {

class Diagnostics {
public:
    Diagnostics(pn_log_fn log, void* log_user) : log_(log), log_user_(log_user) {}

    // One line to the app's log callback, if it gave one.
    void log(int32_t level, const char* source, const char* msg) const noexcept {
        if (log_) log_(log_user_, level, source ? source : "", msg ? msg : "");
    }
    // A line that is logged and, at PNP_LOG_WARN and above, kept as
    // "<source>: <msg>" in the description's warnings.
    void note(int32_t level, const char* source, const char* msg) noexcept;
    void warn(const char* source, const char* msg) noexcept { note(PNP_LOG_WARN, source, msg); }

    const std::vector<std::string>& warnings() const { return warnings_; }
    uint64_t warning_count() const { return warning_count_; }

private:
    static constexpr size_t kMaxWarningsKept = 200;

    pn_log_fn log_;
    void* log_user_;
    std::vector<std::string> warnings_;
    uint64_t warning_count_ = 0;
};

// What a pnp_host_t given to plugin code points back to: who is speaking
// (an instance name such as "foot/step_detector", or a library id for the
// library's init) and the engine that listens.
struct HostContext {
    pnp_host_t host{};
    std::string source;
    Diagnostics* diagnostics = nullptr;
    GeoOrigin* origin = nullptr;
};

// Fills context->host (abi_version, struct_size, every slot) to point back at context.
void init_host(HostContext* context);

}  // namespace pednav::engine
