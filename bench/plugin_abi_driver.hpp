// SPDX-License-Identifier: Apache-2.0
// Drives one plugin through the plugin ABI as the engine does (dlopen,
// pnp_entry_v1, create with params, process per record into a sink that
// copies the records out), for the benchmarks of single plugins.
#pragma once

#include <dlfcn.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_plugin.h>

#include "record_copy.hpp"

namespace pednav::bench {

struct PluginNode {
    const pnp_node_ops_t* ops = nullptr;
    void* self = nullptr;
};

// A sink that keeps the records of one process call.
struct RecordSink {
    pnp_sink_t sink{};
    std::vector<std::array<unsigned char, PN_RECORD_MAX_SIZE>> records;
    size_t count = 0;
    RecordSink() : records(64) {
        sink.sink_data = this;
        sink.emit = &emit;
    }
    const pn_record_header_t* at(size_t i) const {
        return reinterpret_cast<const pn_record_header_t*>(records[i].data());
    }
    static pn_status_t emit(const pnp_sink_t* s, const pn_record_header_t* r) noexcept {
        auto* self = static_cast<RecordSink*>(s->sink_data);
        if (self->count == self->records.size()) return PN_E_OUT_OF_MEMORY;
        pednav::engine::copy_record(self->records[self->count++].data(), r);
        return PN_OK;
    }
};

// The plugin `id` of the first-party library `library` (in PEDNAV_PLUGIN_OUTPUT_DIR).
inline PluginNode create_plugin(const std::string& library, const std::string& id, const nlohmann::json& params,
                                const char* mount, double rate_hz) {
    void* handle = dlopen((std::string(PEDNAV_PLUGIN_OUTPUT_DIR) + "/" + library).c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) throw std::runtime_error(dlerror());
    auto entry = reinterpret_cast<const pnp_library_t* (*)()>(dlsym(handle, "pnp_entry_v1"));
    if (!entry) throw std::runtime_error(library + ": no pnp_entry_v1");
    const pnp_library_t* lib = entry();
    for (uint32_t i = 0; i < lib->plugin_count; ++i) {
        const pnp_descriptor_t* d = lib->plugins[i];
        if (id != d->id) continue;
        const std::string json = params.dump();
        pnp_create_info_t info{};
        info.abi_version = PN_ABI_VERSION;
        info.struct_size = sizeof info;
        info.params_json = json.c_str();
        info.params_len = static_cast<uint32_t>(json.size());
        info.instance_name = id.c_str();
        info.mount = mount;
        info.imu_rate_hz = rate_hz;
        static const pnp_host_t host{PN_ABI_VERSION, sizeof(pnp_host_t), nullptr, nullptr, nullptr, nullptr};
        pn_error_t err{};
        err.struct_size = sizeof err;
        PluginNode n;
        n.ops = d->ops;
        if (d->create(d, &host, &info, &n.self, &err) != PN_OK) throw std::runtime_error(id + ": " + err.message);
        return n;
    }
    throw std::runtime_error(library + ": no plugin " + id);
}

}  // namespace pednav::bench
