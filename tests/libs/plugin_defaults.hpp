// SPDX-License-Identifier: Apache-2.0
// The defaults of a first-party plugin's parameters, read from its parameter
// schema in the built plugin library: the one place defaults are written. The
// library tests build their configs from them (navmath::strapdown_config,
// zupt_ins::shoe_config, ...) and change only what a test is about.
#pragma once

#include <dlfcn.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>
#include <pednav/pn_plugin.h>

namespace pednav::test {

class PluginDefaults {
public:
    // `library` is the file name in the first-party plugin directory
    // ("libpnp_foot_stance.so"), `id` the plugin's id.
    PluginDefaults(const std::string& library, const std::string& id) {
        const std::string path = std::string(PEDNAV_PLUGIN_OUTPUT_DIR) + "/" + library;
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) throw std::runtime_error("cannot open " + path + ": " + dlerror());
        auto entry = reinterpret_cast<pnp_entry_fn>(dlsym(handle, PNP_ENTRY_SYMBOL));
        const pnp_library_t* lib = entry ? entry() : nullptr;
        for (uint32_t i = 0; lib && i < lib->plugin_count; ++i) {
            const pnp_descriptor_t* d = lib->plugins[i];
            if (id != d->id) continue;
            if (!d->params_schema_json) throw std::runtime_error(id + " has no parameter schema");
            const auto schema = nlohmann::json::parse(d->params_schema_json);
            for (const auto& [key, spec] : schema.at("properties").items()) defaults_[key] = spec.at("default");
        }
        dlclose(handle);  // the values are copied: nothing points into the library
        if (defaults_.empty()) throw std::runtime_error("no plugin " + id + " with parameters in " + path);
    }

    double number(const std::string& key) const { return at(key).get<double>(); }
    bool boolean(const std::string& key) const { return at(key).get<bool>(); }
    long integer(const std::string& key) const { return at(key).get<long>(); }

private:
    const nlohmann::json& at(const std::string& key) const {
        auto it = defaults_.find(key);
        if (it == defaults_.end()) throw std::runtime_error("no parameter " + key + " in the schema");
        return *it;
    }
    nlohmann::json defaults_ = nlohmann::json::object();
};

}  // namespace pednav::test
