// Finds, opens and validates plugin libraries. Nothing is loaded implicitly:
// only files named libpnp_*.so in the directories the app gives, and the
// libraries it links in statically. Every file that is refused is kept with
// the reason, for pn_engine_describe and `pednav plugins`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <pednav/pn_plugin.h>

namespace pednav::engine {

struct RejectedFile {
    std::string path;
    pn_status_t status;
    std::string reason;
};

struct LoadedLibrary {
    std::string path;   // file path, or "<static:N>"
    void* handle;       // dlopen handle, NULL for static libraries
    const pnp_library_t* library;
    int init_count = 0; // init() called (0/1); deinit() at unload
};

struct AvailablePlugin {
    const pnp_descriptor_t* descriptor;
    size_t library_index;  // into Loader::libraries()
};

class Loader {
public:
    Loader() = default;
    Loader(const Loader&) = delete;
    Loader& operator=(const Loader&) = delete;
    ~Loader();  // deinit()s and dlclose()s: destroy every instance first

    // Opens every libpnp_*.so in `dir` (sorted by name). A missing directory
    // is itself reported as rejected.
    void scan_directory(const std::string& dir);
    void add_static_library(const pnp_library_t* library, const std::string& label);

    const std::vector<LoadedLibrary>& libraries() const { return libraries_; }
    const std::vector<RejectedFile>& rejected() const { return rejected_; }
    const std::vector<AvailablePlugin>& plugins() const { return plugins_; }
    const AvailablePlugin* find(const std::string& id) const;
    // Why an id is not available, if a rejected file declared it; empty otherwise.
    std::string rejection_for(const std::string& id) const;

    // Calls the library's init() once, before its first instance.
    pn_status_t ensure_init(size_t library_index, const pnp_host_t* host, pn_error_t* err);

private:
    void add_library(const pnp_library_t* library, void* handle, const std::string& path);
    void reject(const std::string& path, pn_status_t status, const std::string& reason);

    std::vector<LoadedLibrary> libraries_;
    std::vector<RejectedFile> rejected_;
    std::vector<AvailablePlugin> plugins_;
    std::map<std::string, std::string> rejected_ids_;  // id -> reason
};

const char* kind_name(pnp_kind_t kind);  // "step_detector", ... or "unknown"

}  // namespace pednav::engine
