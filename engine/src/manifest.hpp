// SPDX-License-Identifier: Apache-2.0
// Plugin manifests: the small JSON file written beside each plugin library at
// build time (libpnp_foot_ekf.json next to libpnp_foot_ekf.so) by the
// pednav-manifest tool, from the library's own descriptors. The loader reads
// them to know which library provides which plugin id without opening any
// library, and checks them against the descriptors of the libraries it opens.
// docs/loading.md describes the format.
#pragma once

#include <string>
#include <vector>

#include <pednav/pn_plugin.h>
#include <nlohmann/json.hpp>

namespace pednav::engine {

constexpr const char* kManifestFormat = "pednav-plugin-manifest/1";

struct ManifestPlugin {
    std::string id;
    pnp_kind_t kind;
    nlohmann::json entry;  // the plugin as describe lists it, without "library"
};

struct Manifest {
    std::string path;  // of the .json file
    std::string file;  // the library file name it describes ("libpnp_foot_ekf.so")
    std::string library_id;
    std::string library_version;
    uint32_t abi_major = 0;
    uint32_t abi_minor = 0;
    std::vector<ManifestPlugin> plugins;
};

// A manifest that cannot be used; the message names the member at fault as a
// JSON pointer ("/plugins/2/kind: ...").
struct ManifestError {
    pn_status_t status;  // PN_E_IO (unreadable) or PN_E_BAD_INPUT (malformed)
    std::string message;
};

// Reads and checks a manifest file. Throws ManifestError.
Manifest read_manifest(const std::string& path);
// The same from text already read (`path` only names it in errors).
Manifest parse_manifest(const std::string& text, const std::string& path);

// The manifest of a validated library, for the file name `file`.
nlohmann::json manifest_json(const pnp_library_t* library, const std::string& file);

// How a library opened from disk differs from its manifest (library id, ABI
// major, plugin ids and kinds); empty when they agree.
std::string manifest_disagreement(const Manifest& manifest, const pnp_library_t* library);

// "libpnp_foot_ekf.so" -> "libpnp_foot_ekf.json", in the same directory.
std::string manifest_path_for(const std::string& library_path);

}  // namespace pednav::engine
