#include "loader.hpp"

#include <dirent.h>
#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <cstring>

namespace pednav::engine {

const char* kind_name(pnp_kind_t kind) {
    switch (kind) {
        case PNP_KIND_STEP_DETECTOR: return "step_detector";
        case PNP_KIND_ATTITUDE_ESTIMATOR: return "attitude_estimator";
        case PNP_KIND_POSITION_FILTER: return "position_filter";
        case PNP_KIND_MAP_MATCHER: return "map_matcher";
        default: return "unknown";
    }
}

namespace {

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const char* suffix) {
    const size_t n = std::strlen(suffix);
    return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

std::string real_path(const std::string& path) {
    char buf[PATH_MAX];
    return realpath(path.c_str(), buf) ? std::string(buf) : path;
}

// The one a library would export under another ABI major, if any.
std::string other_major_entry(void* handle) {
    for (int major = 0; major <= 16; ++major) {
        if (major == PN_ABI_MAJOR) continue;
        const std::string name = "pnp_entry_v" + std::to_string(major);
        if (dlsym(handle, name.c_str())) return name;
    }
    return {};
}

std::string check_descriptor(const pnp_descriptor_t* d) {
    if (!d) return "a plugin descriptor pointer is NULL";
    if (PN_ABI_VERSION_MAJOR(d->abi_version) != PN_ABI_MAJOR)
        return "descriptor ABI major " + std::to_string(PN_ABI_VERSION_MAJOR(d->abi_version)) +
               ", this engine supports " + std::to_string(PN_ABI_MAJOR);
    if (d->struct_size < PNP_DESCRIPTOR_MIN_SIZE)
        return "descriptor struct_size " + std::to_string(d->struct_size) + " is below the minimum " +
               std::to_string(PNP_DESCRIPTOR_MIN_SIZE);
    if (!d->id || !*d->id) return "a descriptor has no id";
    const std::string id = d->id;
    if (std::strcmp(kind_name(d->kind), "unknown") == 0)
        return "plugin " + id + " has unknown kind " + std::to_string(d->kind);
    if (!d->create) return "plugin " + id + " has no create function";
    if (!d->ops) return "plugin " + id + " has no vtable";
    if (d->ops->struct_size < PNP_NODE_OPS_MIN_SIZE)
        return "plugin " + id + " vtable struct_size " + std::to_string(d->ops->struct_size) +
               " is below the minimum " + std::to_string(PNP_NODE_OPS_MIN_SIZE);
    if (!d->ops->destroy || !d->ops->reset || !d->ops->process)
        return "plugin " + id + " lacks a required slot (destroy, reset or process)";
    return {};
}

}  // namespace

Loader::~Loader() {
    for (auto it = libraries_.rbegin(); it != libraries_.rend(); ++it) {
        if (it->init_count > 0 && it->library->deinit) it->library->deinit();
        if (it->handle) dlclose(it->handle);
    }
}

void Loader::reject(const std::string& path, pn_status_t status, const std::string& reason) {
    rejected_.push_back({path, status, reason});
}

void Loader::scan_directory(const std::string& dir) {
    DIR* d = opendir(dir.c_str());
    if (!d) {
        reject(dir, PN_E_NOT_FOUND, std::string("plugin directory cannot be opened: ") + std::strerror(errno));
        return;
    }
    std::vector<std::string> names;
    while (dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (starts_with(name, "libpnp_") && ends_with(name, ".so")) names.push_back(name);
    }
    closedir(d);
    std::sort(names.begin(), names.end());
    for (const auto& name : names) {
        const std::string path = real_path(dir + "/" + name);
        bool seen = false;
        for (const auto& l : libraries_) seen = seen || l.path == path;
        if (seen) continue;  // the same file reached through two directories
        dlerror();
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* e = dlerror();
            reject(path, PN_E_IO, std::string("dlopen failed: ") + (e ? e : "unknown error"));
            continue;
        }
        void* sym = dlsym(handle, PNP_ENTRY_SYMBOL);
        if (!sym) {
            const std::string other = other_major_entry(handle);
            if (!other.empty())
                reject(path, PN_E_ABI_MISMATCH,
                       "exports " + other + " (another ABI major) but not " PNP_ENTRY_SYMBOL
                       "; this engine speaks ABI major " + std::to_string(PN_ABI_MAJOR));
            else
                reject(path, PN_E_NOT_FOUND, "no entry symbol " PNP_ENTRY_SYMBOL ": not a pednav plugin");
            dlclose(handle);
            continue;
        }
        Dl_info info;
        if (dladdr(sym, &info) == 0 || !info.dli_fname || real_path(info.dli_fname) != path) {
            reject(path, PN_E_ABI_MISMATCH,
                   std::string("entry symbol comes from another object (") +
                       (info.dli_fname ? info.dli_fname : "?") + "), not from this file");
            dlclose(handle);
            continue;
        }
        const pnp_library_t* lib = reinterpret_cast<pnp_entry_fn>(sym)();
        const size_t before = libraries_.size();
        add_library(lib, handle, path);
        if (libraries_.size() == before) dlclose(handle);
    }
}

void Loader::add_static_library(const pnp_library_t* library, const std::string& label) {
    add_library(library, nullptr, label);
}

void Loader::add_library(const pnp_library_t* lib, void* handle, const std::string& path) {
    if (!lib) return reject(path, PN_E_ABI_MISMATCH, "entry function returned NULL");
    if (PN_ABI_VERSION_MAJOR(lib->abi_version) != PN_ABI_MAJOR)
        return reject(path, PN_E_ABI_MISMATCH,
                      "library ABI major " + std::to_string(PN_ABI_VERSION_MAJOR(lib->abi_version)) +
                          ", this engine speaks " + std::to_string(PN_ABI_MAJOR));
    if (lib->struct_size < PNP_LIBRARY_MIN_SIZE)
        return reject(path, PN_E_ABI_MISMATCH,
                      "library struct_size " + std::to_string(lib->struct_size) +
                          " is below the minimum " + std::to_string(PNP_LIBRARY_MIN_SIZE));
    if (lib->plugin_count == 0 || !lib->plugins)
        return reject(path, PN_E_NOT_FOUND, "library declares no plugins");
    std::vector<const pnp_descriptor_t*> good;
    for (uint32_t i = 0; i < lib->plugin_count; ++i) {
        const pnp_descriptor_t* d = lib->plugins[i];
        const std::string problem = check_descriptor(d);
        if (!problem.empty()) {
            if (d && d->id) rejected_ids_[d->id] = problem + " (" + path + ")";
            reject(path, PN_E_ABI_MISMATCH, problem);
            continue;
        }
        if (const AvailablePlugin* prior = find(d->id)) {
            const std::string& other = libraries_[prior->library_index].path;
            reject(path, PN_E_INVALID_ARGUMENT,
                   std::string("duplicate plugin id ") + d->id + ": already provided by " + other);
            continue;
        }
        bool twice = false;
        for (const auto* g : good) twice = twice || std::strcmp(g->id, d->id) == 0;
        if (twice) {
            reject(path, PN_E_INVALID_ARGUMENT, std::string("duplicate plugin id ") + d->id + " within the library");
            continue;
        }
        good.push_back(d);
    }
    if (good.empty()) return;
    libraries_.push_back({path, handle, lib, 0});
    for (const auto* d : good) plugins_.push_back({d, libraries_.size() - 1});
}

const AvailablePlugin* Loader::find(const std::string& id) const {
    for (const auto& p : plugins_)
        if (id == p.descriptor->id) return &p;
    return nullptr;
}

std::string Loader::rejection_for(const std::string& id) const {
    auto it = rejected_ids_.find(id);
    return it == rejected_ids_.end() ? std::string() : it->second;
}

pn_status_t Loader::ensure_init(size_t library_index, const pnp_host_t* host, pn_error_t* err) {
    LoadedLibrary& l = libraries_[library_index];
    if (l.init_count > 0) return PN_OK;
    if (PNP_HAS_SLOT(l.library, pnp_library_t, init)) {
        const pn_status_t s = l.library->init(host, err);
        if (PN_FAILED(s)) return s;
    }
    l.init_count = 1;
    return PN_OK;
}

}  // namespace pednav::engine
