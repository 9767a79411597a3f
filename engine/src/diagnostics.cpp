// SPDX-License-Identifier: Apache-2.0
// Diagnostics and the host slots plugin code calls (pnp_host_t).
#include "diagnostics.hpp"

#include <new>

namespace pednav::engine {

const char* GeoOrigin::source_name(Source s) {
    switch (s) {
        case Source::none: return "none";
        case Source::config: return "the config";
        case Source::app: return "the app";
        case Source::plugin: return "a plugin";
        case Source::gnss_fix: return "a GNSS fix";
    }
    return "unknown";
}

void Diagnostics::note(int32_t level, const char* source, const char* msg) noexcept {
    log(level, source, msg);
    if (level < PNP_LOG_WARN) return;
    ++warning_count_;
    if (warnings_.size() >= kMaxWarningsKept) return;
    try {
        std::string line = source && *source ? std::string(source) + ": " : std::string();
        line += msg ? msg : "";
        warnings_.push_back(std::move(line));
    } catch (const std::bad_alloc&) {
        // Counted above; the text is lost, the engine goes on.
    }
}

namespace {

const HostContext* context_of(const pnp_host_t* host) {
    return host ? static_cast<const HostContext*>(host->host_data) : nullptr;
}

void host_log(const pnp_host_t* host, pnp_log_level_t level, const char* msg) noexcept {
    const HostContext* c = context_of(host);
    if (!c || !c->diagnostics) return;
    if (level < PNP_LOG_DEBUG) level = PNP_LOG_DEBUG;
    if (level > PNP_LOG_ERROR) level = PNP_LOG_ERROR;
    c->diagnostics->note(level, c->source.c_str(), msg);
}

pn_status_t host_get_origin(const pnp_host_t* host, pn_geo_point_t* origin) noexcept {
    const HostContext* c = context_of(host);
    if (!c || !c->origin || !origin) return PN_E_INVALID_ARGUMENT;
    if (!c->origin->known()) return PN_NO_DATA;
    *origin = c->origin->point();
    return PN_OK;
}

pn_status_t host_offer_origin(const pnp_host_t* host, const pn_geo_point_t* origin) noexcept {
    const HostContext* c = context_of(host);
    if (!c || !c->origin || !origin || !GeoOrigin::valid(*origin)) return PN_E_INVALID_ARGUMENT;
    return c->origin->set(*origin, GeoOrigin::Source::plugin, c->source.c_str()) ? PN_OK : PN_E_BAD_STATE;
}

}  // namespace

void init_host(HostContext* c) {
    c->host.abi_version = PN_ABI_VERSION;
    c->host.struct_size = sizeof(pnp_host_t);
    c->host.host_data = c;
    c->host.log = &host_log;
    c->host.get_origin = &host_get_origin;
    c->host.offer_origin = &host_offer_origin;
}

}  // namespace pednav::engine
