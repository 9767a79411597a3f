// SPDX-License-Identifier: Apache-2.0
// Finds, opens and validates plugin libraries. Nothing is loaded implicitly:
// only files named libpnp_*.so in the directories the app gives, and the
// libraries it links in statically.
//
// Finding and opening are separate steps. scan_directory() reads the manifest
// beside each library (manifest.hpp) and opens nothing; open_for() then opens
// only the libraries that provide the plugin ids a config names, and checks
// each against its manifest. A library without a usable manifest is opened
// only when a wanted id is in no manifest. Every file that is refused is kept
// with the reason, for pn_engine_describe and `pednav plugins`.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <pednav/pn_plugin.h>

#include "manifest.hpp"

namespace pednav::engine {

struct RejectedFile {
    std::string path;
    pn_status_t status;
    std::string reason;
};

// Found and usable, but worth a look (a library without a manifest).
struct LoadWarning {
    std::string path;
    std::string message;
};

// A plugin library the loader knows of.
struct LibraryFile {
    std::string path;                        // real file path, or "<static:N>"
    std::optional<Manifest> manifest;        // the manifest beside it, if one was read and accepted
    void* handle = nullptr;                  // dlopen handle once opened; NULL for static libraries
    const pnp_library_t* library = nullptr;  // set once opened (static libraries: at once)
    bool refused = false;                    // none of its plugins is offered (see rejected())
    bool init_done = false;                  // init() called; deinit() at unload
};

// A plugin id on offer: listed by a manifest, or read from an opened library.
struct AvailablePlugin {
    std::string id;
    pnp_kind_t kind;
    size_t library_index;                          // into Loader::libraries()
    const pnp_descriptor_t* descriptor = nullptr;  // NULL until its library is opened
    int manifest_entry = -1;                       // index into the library's manifest plugins, -1 if none
};

class Loader {
public:
    Loader() = default;
    Loader(const Loader&) = delete;
    Loader& operator=(const Loader&) = delete;
    ~Loader();  // deinit()s and dlclose()s: destroy every instance first

    // Finds every libpnp_*.so in `dir` (sorted by name) and reads the manifest
    // beside it; opens nothing. A missing directory is itself reported as rejected.
    void scan_directory(const std::string& dir);
    void add_static_library(const pnp_library_t* library, const std::string& label);
    // Opens the libraries that provide these ids: the one whose manifest lists
    // an id, and, for ids in no manifest, the libraries without a manifest in
    // turn until every id is found.
    void open_for(const std::vector<std::string>& ids);
    // Opens every library found (listing tools that check the manifests).
    void open_all();
    // Opens one library file, with no manifest (the manifest tool). False if it is refused.
    bool open_file(const std::string& path);

    const std::vector<LibraryFile>& libraries() const { return libraries_; }
    const std::vector<RejectedFile>& rejected() const { return rejected_; }
    const std::vector<LoadWarning>& warnings() const { return warnings_; }
    // Every plugin on offer, in the order found (opened or only listed).
    const std::vector<AvailablePlugin>& plugins() const { return plugins_; }
    // A plugin whose library is open and accepted; NULL otherwise.
    const AvailablePlugin* find(const std::string& id) const;
    // Why an id is not available, if a refused file declared it; empty otherwise.
    std::string rejection_for(const std::string& id) const;

    // Calls the library's init() once, before its first instance.
    pn_status_t ensure_init(size_t library_index, const pnp_host_t* host, pn_error_t* err);

private:
    void add_found_file(const std::string& dir, const std::string& name);
    void list_manifest_plugins(size_t index);
    void open_library(size_t index);
    bool accept_library(size_t index, const pnp_library_t* library);
    void add_descriptors(size_t index);
    void refuse(size_t index, pn_status_t status, const std::string& reason);
    AvailablePlugin* entry_for(const std::string& id);
    void reject(const std::string& path, pn_status_t status, const std::string& reason);

    std::vector<LibraryFile> libraries_;
    std::vector<RejectedFile> rejected_;
    std::vector<LoadWarning> warnings_;
    std::vector<AvailablePlugin> plugins_;
    std::map<std::string, std::string> rejected_ids_;  // id -> reason
};

const char* kind_name(pnp_kind_t kind);              // "step_detector", ... or "unknown"
pnp_kind_t kind_from_name(const std::string& name);  // 0 for an unknown name

}  // namespace pednav::engine
