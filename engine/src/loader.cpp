// SPDX-License-Identifier: Apache-2.0
#include "loader.hpp"

#include <dirent.h>
#include <dlfcn.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <set>

#include "library_bounds.hpp"

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

pnp_kind_t kind_from_name(const std::string& name) {
    for (pnp_kind_t k : {PNP_KIND_STEP_DETECTOR, PNP_KIND_ATTITUDE_ESTIMATOR, PNP_KIND_POSITION_FILTER,
                         PNP_KIND_MAP_MATCHER})
        if (name == kind_name(k)) return k;
    return 0;
}

namespace {

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool ends_with(const std::string& s, const char* suffix) {
    const size_t n = std::strlen(suffix);
    return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}
bool is_file(const std::string& path) {
    struct stat st;
    return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string real_path(const std::string& path) {
    char buf[PATH_MAX];
    return realpath(path.c_str(), buf) ? std::string(buf) : path;
}

std::string octal_mode(mode_t mode) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%04o", static_cast<unsigned>(mode & 07777));
    return buf;
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

std::string check_library(const pnp_library_t* lib) {
    if (!lib) return "entry function returned NULL";
    if (PN_ABI_VERSION_MAJOR(lib->abi_version) != PN_ABI_MAJOR)
        return "library ABI major " + std::to_string(PN_ABI_VERSION_MAJOR(lib->abi_version)) +
               ", this engine speaks " + std::to_string(PN_ABI_MAJOR);
    if (lib->struct_size < PNP_LIBRARY_MIN_SIZE)
        return "library struct_size " + std::to_string(lib->struct_size) + " is below the minimum " +
               std::to_string(PNP_LIBRARY_MIN_SIZE);
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

// For a library opened from disk: that what it hands over lies in its own
// memory before anything is read through it (the plugins array for
// plugin_count entries, each descriptor, its vtable and its id). Empty when it
// does; the reason otherwise.
std::string check_bounds(const LibraryBounds& bounds, const pnp_library_t* lib) {
    if (!lib->plugins || lib->plugin_count == 0) return {};
    const std::string count = "plugin_count " + std::to_string(lib->plugin_count);
    if (!bounds.holds(lib->plugins, sizeof(void*) * lib->plugin_count))
        return count + " runs past the library's memory: the plugins array is shorter";
    for (uint32_t i = 0; i < lib->plugin_count; ++i) {
        const pnp_descriptor_t* d = lib->plugins[i];
        const std::string at = "plugins[" + std::to_string(i) + "] (" + count + ")";
        if (!d) continue;  // refused by the descriptor checks, with its own reason
        if (!bounds.holds(d, PNP_DESCRIPTOR_MIN_SIZE))
            return at + " does not point at a descriptor in the library: is plugin_count larger than the array?";
        if (d->id && !bounds.holds_string(d->id)) return at + " has an id outside the library";
        if (d->ops && !bounds.holds(d->ops, PNP_NODE_OPS_MIN_SIZE)) return at + " has a vtable outside the library";
    }
    return {};
}

// The trust model (README, "Trust model"): a plugin directory or library that
// anyone may write to, or a link leading out of the directory, could hand the
// app code it did not choose; they are refused, with the reason.
std::string untrusted_directory(const std::string& dir) {
    struct stat st;
    if (stat(dir.c_str(), &st) != 0) return std::string("cannot stat the directory: ") + std::strerror(errno);
    if (st.st_mode & S_IWOTH)
        return "the plugin directory is world-writable (mode " + octal_mode(st.st_mode) +
               "): anyone could put a library there; not scanned";
    return {};
}

std::string untrusted_library(const std::string& dir, const std::string& name) {
    const std::string link = dir + "/" + name;
    struct stat lst, st;
    if (lstat(link.c_str(), &lst) != 0 || stat(link.c_str(), &st) != 0)
        return std::string("cannot stat the file: ") + std::strerror(errno);
    if (S_ISLNK(lst.st_mode)) {
        const std::string target = real_path(link), base = real_path(dir) + "/";
        if (target.compare(0, base.size(), base) != 0)
            return name + " is a symbolic link to " + target + ", outside the plugin directory " + real_path(dir) +
                   ": not opened";
    }
    if (!S_ISREG(st.st_mode)) return "not a regular file";
    if (st.st_mode & S_IWOTH)
        return "the library is world-writable (mode " + octal_mode(st.st_mode) + "): anyone could change it; not opened";
    return {};
}

constexpr const char* kNoManifest =
    ": it is opened only when a configured plugin id is in no manifest (pednav_add_plugin writes one)";

// Engines in several threads open and close the same libraries. glibc locks
// dlopen and dlclose internally, but what they hand back (the link map read by
// LibraryBounds, the file name from dladdr) is read after that lock is
// released, while another thread's dlopen of the same file may still be filling
// it in. One lock per process around opening, checking and closing a library
// makes those reads ordered.
std::mutex& library_mutex() {
    static std::mutex m;
    return m;
}

}  // namespace

Loader::~Loader() {
    const std::lock_guard<std::mutex> lock(library_mutex());
    for (auto it = libraries_.rbegin(); it != libraries_.rend(); ++it) {
        if (it->init_done && it->library->deinit) it->library->deinit();
        if (it->handle) dlclose(it->handle);
    }
}

void Loader::reject(const std::string& path, pn_status_t status, const std::string& reason) {
    rejected_.push_back({path, status, reason});
}

AvailablePlugin* Loader::entry_for(const std::string& id) {
    for (auto& p : plugins_)
        if (p.id == id) return &p;
    return nullptr;
}

const AvailablePlugin* Loader::find(const std::string& id) const {
    for (const auto& p : plugins_)
        if (p.id == id) return p.descriptor ? &p : nullptr;
    return nullptr;
}

std::string Loader::rejection_for(const std::string& id) const {
    auto it = rejected_ids_.find(id);
    return it == rejected_ids_.end() ? std::string() : it->second;
}

void Loader::scan_directory(const std::string& dir) {
    DIR* d = opendir(dir.c_str());
    if (!d) {
        reject(dir, PN_E_NOT_FOUND,
               std::string("plugin directory cannot be opened: ") + std::strerror(errno));
        return;
    }
    if (const std::string why = untrusted_directory(dir); !why.empty()) {
        closedir(d);
        reject(real_path(dir), PN_E_IO, why);
        return;
    }
    std::vector<std::string> libraries;
    std::set<std::string> manifests;
    while (dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (!starts_with(name, "libpnp_")) continue;
        if (ends_with(name, ".so"))
            libraries.push_back(name);
        else if (ends_with(name, ".json"))
            manifests.insert(name);
    }
    closedir(d);
    std::sort(libraries.begin(), libraries.end());
    for (const auto& name : libraries) {
        manifests.erase(manifest_path_for(name));
        add_found_file(dir, name);
    }
    for (const auto& m : manifests)
        warnings_.push_back(
            {real_path(dir + "/" + m),
             "manifest without its library " + m.substr(0, m.size() - 5) + ".so beside it: ignored"});
}

void Loader::add_found_file(const std::string& dir, const std::string& name) {
    const std::string path = real_path(dir + "/" + name);
    for (const auto& l : libraries_)
        if (l.path == path) return;  // the same file reached through two directories
    if (const std::string why = untrusted_library(dir, name); !why.empty()) return reject(path, PN_E_IO, why);
    LibraryFile file;
    file.path = path;
    const std::string manifest = real_path(manifest_path_for(dir + "/" + name));
    if (!is_file(manifest)) {
        warnings_.push_back({path, "no manifest " + manifest_path_for(name) + " beside it" + kNoManifest});
    } else {
        try {
            Manifest m = read_manifest(manifest);
            if (m.file != name)
                throw ManifestError{PN_E_BAD_INPUT,
                                    "manifest " + manifest + " describes " + m.file + ", not " + name};
            file.manifest = std::move(m);
        } catch (const ManifestError& e) {
            reject(manifest, e.status, e.message);
            warnings_.push_back(
                {path, "its manifest " + manifest_path_for(name) + " is refused" + kNoManifest});
        }
    }
    libraries_.push_back(std::move(file));
    if (libraries_.back().manifest) list_manifest_plugins(libraries_.size() - 1);
}

void Loader::list_manifest_plugins(size_t index) {
    const LibraryFile& file = libraries_[index];
    const Manifest& m = *file.manifest;
    if (m.abi_major != PN_ABI_MAJOR)
        return refuse(index, PN_E_ABI_MISMATCH,
                      "its manifest says ABI major " + std::to_string(m.abi_major) + ", this engine speaks " +
                          std::to_string(PN_ABI_MAJOR) + ": not opened");
    for (size_t k = 0; k < m.plugins.size(); ++k) {
        const ManifestPlugin& p = m.plugins[k];
        if (const AvailablePlugin* prior = entry_for(p.id)) {
            reject(file.path, PN_E_INVALID_ARGUMENT,
                   "duplicate plugin id " + p.id + ": already provided by " +
                       libraries_[prior->library_index].path);
            continue;
        }
        plugins_.push_back({p.id, p.kind, index, nullptr, static_cast<int>(k)});
    }
}

void Loader::add_static_library(const pnp_library_t* library, const std::string& label) {
    LibraryFile file;
    file.path = label;
    libraries_.push_back(std::move(file));
    const size_t index = libraries_.size() - 1;
    if (accept_library(index, library)) add_descriptors(index);
}

void Loader::open_for(const std::vector<std::string>& ids) {
    for (const auto& id : ids)
        if (const AvailablePlugin* p = entry_for(id); p && !p->descriptor) open_library(p->library_index);
    auto missing = [&] {
        for (const auto& id : ids)
            if (!find(id)) return true;
        return false;
    };
    for (size_t i = 0; i < libraries_.size() && missing(); ++i)
        if (!libraries_[i].manifest) open_library(i);
}

void Loader::open_all() {
    for (size_t i = 0; i < libraries_.size(); ++i) open_library(i);
}

bool Loader::open_file(const std::string& path) {
    LibraryFile file;
    file.path = real_path(path);
    libraries_.push_back(std::move(file));
    open_library(libraries_.size() - 1);
    return !libraries_.back().refused;
}

void Loader::refuse(size_t index, pn_status_t status, const std::string& reason) {
    LibraryFile& file = libraries_[index];
    file.refused = true;
    reject(file.path, status, reason);
    if (file.manifest)
        for (const auto& p : file.manifest->plugins)
            rejected_ids_.emplace(p.id, reason + " (" + file.path + ")");
    plugins_.erase(std::remove_if(plugins_.begin(), plugins_.end(),
                                  [&](const AvailablePlugin& p) { return p.library_index == index; }),
                   plugins_.end());
}

void Loader::open_library(size_t index) {
    if (libraries_[index].library || libraries_[index].refused) return;
    const std::lock_guard<std::mutex> lock(library_mutex());
    const std::string path = libraries_[index].path;
    dlerror();
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* e = dlerror();
        return refuse(index, PN_E_IO, std::string("dlopen failed: ") + (e ? e : "unknown error"));
    }
    void* sym = dlsym(handle, PNP_ENTRY_SYMBOL);
    std::string problem;
    pn_status_t status = PN_E_ABI_MISMATCH;
    Dl_info info{};
    if (!sym) {
        const std::string other = other_major_entry(handle);
        if (!other.empty()) {
            problem = "exports " + other +
                      " (another ABI major) but not " PNP_ENTRY_SYMBOL "; this engine speaks ABI major " +
                      std::to_string(PN_ABI_MAJOR);
        } else {
            status = PN_E_NOT_FOUND;
            problem = "no entry symbol " PNP_ENTRY_SYMBOL ": not a pednav plugin";
        }
    } else if (dladdr(sym, &info) == 0 || !info.dli_fname || real_path(info.dli_fname) != path) {
        problem = std::string("entry symbol comes from another object (") +
                  (info.dli_fname ? info.dli_fname : "?") + "), not from this file";
    }
    if (!problem.empty()) {
        dlclose(handle);
        return refuse(index, status, problem);
    }
    libraries_[index].handle = handle;
    if (!accept_library(index, reinterpret_cast<pnp_entry_fn>(sym)())) return;
    add_descriptors(index);
}

// Checks the library struct and, for a library with a manifest, that both say
// the same. Refuses (and closes) the library otherwise.
bool Loader::accept_library(size_t index, const pnp_library_t* library) {
    LibraryFile& file = libraries_[index];
    std::string problem;
    pn_status_t status = PN_E_ABI_MISMATCH;
    // Opened from disk: what it hands over is bounded by its own memory before it is read.
    const std::optional<LibraryBounds> bounds =
        file.handle ? std::optional<LibraryBounds>(LibraryBounds(file.handle)) : std::nullopt;
    if (library && bounds && !bounds->holds(library, PNP_LIBRARY_MIN_SIZE)) {
        status = PN_E_INVALID_ARGUMENT;
        problem = "entry function returned a pointer outside the library";
    }
    if (problem.empty()) problem = check_library(library);
    if (problem.empty() && bounds) {
        problem = check_bounds(*bounds, library);
        if (!problem.empty()) status = PN_E_INVALID_ARGUMENT;
    }
    if (problem.empty() && (library->plugin_count == 0 || !library->plugins)) {
        status = PN_E_NOT_FOUND;
        problem = "library declares no plugins";
    }
    if (problem.empty() && file.manifest) problem = manifest_disagreement(*file.manifest, library);
    if (problem.empty() && file.manifest && library->plugin_count != file.manifest->plugins.size()) {
        status = PN_E_INVALID_ARGUMENT;
        problem = "plugin_count " + std::to_string(library->plugin_count) + ", but its manifest " + file.manifest->path +
                  " lists " + std::to_string(file.manifest->plugins.size()) + " plugins";
    }
    if (problem.empty()) {
        file.library = library;
        return true;
    }
    if (file.handle) dlclose(file.handle);
    file.handle = nullptr;
    refuse(index, status, problem);
    return false;
}

void Loader::add_descriptors(size_t index) {
    LibraryFile& file = libraries_[index];
    const pnp_library_t* lib = file.library;
    size_t offered = 0;
    for (uint32_t i = 0; i < lib->plugin_count; ++i) {
        const pnp_descriptor_t* d = lib->plugins[i];
        const std::string problem = check_descriptor(d);
        if (!problem.empty()) {
            if (d && d->id) {
                rejected_ids_[d->id] = problem + " (" + file.path + ")";
                plugins_.erase(std::remove_if(plugins_.begin(), plugins_.end(),
                                              [&](const AvailablePlugin& p) {
                                                  return p.library_index == index && p.id == d->id;
                                              }),
                               plugins_.end());
            }
            reject(file.path, PN_E_ABI_MISMATCH, problem);
            continue;
        }
        AvailablePlugin* entry = entry_for(d->id);
        if (entry && entry->library_index != index) {
            bool reported = false;  // from the manifest, when it was read
            if (file.manifest)
                for (const auto& p : file.manifest->plugins) reported = reported || p.id == d->id;
            if (!reported)
                reject(file.path, PN_E_INVALID_ARGUMENT,
                       std::string("duplicate plugin id ") + d->id + ": already provided by " +
                           libraries_[entry->library_index].path);
        } else if (entry && entry->descriptor) {
            reject(file.path, PN_E_INVALID_ARGUMENT,
                   std::string("duplicate plugin id ") + d->id + " within the library");
        } else if (entry) {
            entry->descriptor = d;  // listed by the manifest
            ++offered;
        } else {
            plugins_.push_back({d->id, d->kind, index, d, -1});
            ++offered;
        }
    }
    if (offered == 0) {  // every plugin refused, each with its reason: nothing to keep open
        if (file.handle) dlclose(file.handle);
        file.handle = nullptr;
        file.library = nullptr;
        file.refused = true;
    }
}

pn_status_t Loader::ensure_init(size_t library_index, const pnp_host_t* host, pn_error_t* err) {
    LibraryFile& l = libraries_[library_index];
    if (l.init_done) return PN_OK;
    if (PNP_HAS_SLOT(l.library, pnp_library_t, init)) {
        const pn_status_t s = l.library->init(host, err);
        if (PN_FAILED(s)) return s;
    }
    l.init_done = true;
    return PN_OK;
}

}  // namespace pednav::engine
