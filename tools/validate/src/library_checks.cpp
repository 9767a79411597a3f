// SPDX-License-Identifier: Apache-2.0
// "load" and "manifest": what the engine's loader thinks of the file.
#include <pednav/pn_engine.h>
#include <pednav/pn_plugin.h>

#include "checks.hpp"
#include "describe.hpp"
#include "loader.hpp"
#include "manifest.hpp"

namespace pednav::validate {

nlohmann::json check_result(bool passed, const std::string& reason, nlohmann::json detail) {
    return {{"passed", passed}, {"reason", passed ? std::string() : reason}, {"detail", std::move(detail)}};
}

namespace {

std::string abi_text(uint32_t v) {
    return std::to_string(PN_ABI_VERSION_MAJOR(v)) + "." + std::to_string(PN_ABI_VERSION_MINOR(v));
}

std::string base_name(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

nlohmann::json load_check(const std::string& library_path) {
    engine::Loader loader;
    const bool opened = loader.open_file(library_path);
    nlohmann::json detail = {{"engine_abi", abi_text(PN_ABI_VERSION)}};
    std::string reasons;
    for (const auto& r : loader.rejected())
        reasons += (reasons.empty() ? "" : "; ") + r.reason + " (" + pn_status_name(r.status) + ")";
    if (!opened || loader.libraries().empty() || !loader.libraries().front().library)
        return check_result(false, reasons.empty() ? "the loader refused the library" : reasons, detail);
    const pnp_library_t* lib = loader.libraries().front().library;
    detail["library_id"] = lib->id ? lib->id : "";
    detail["library_version"] = lib->version ? lib->version : "";
    detail["abi"] = abi_text(lib->abi_version);
    if (PN_ABI_VERSION_MINOR(lib->abi_version) > PN_ABI_VERSION_MINOR(PN_ABI_VERSION))
        detail["note"] = "built for a newer minor than this engine's: its newer slots are ignored here";
    nlohmann::json plugins = nlohmann::json::array();
    for (const auto& p : loader.plugins())
        if (p.descriptor) plugins.push_back(engine::describe_plugin(p.descriptor));
    detail["plugins"] = plugins;
    if (!reasons.empty()) return check_result(false, reasons, detail);
    if (plugins.empty()) return check_result(false, "the library offers no plugin", detail);
    return check_result(true, "", detail);
}

nlohmann::json manifest_check(const std::string& library_path) {
    const std::string path = engine::manifest_path_for(library_path);
    nlohmann::json detail = {{"manifest", path}};
    engine::Manifest manifest;
    try {
        manifest = engine::read_manifest(path);
    } catch (const engine::ManifestError& e) {
        return check_result(false, e.message + " (pednav-manifest writes it; pednav_add_plugin() runs it after each link)",
                            detail);
    }
    engine::Loader loader;
    if (!loader.open_file(library_path) || !loader.libraries().front().library)
        return check_result(false, "the library does not load (see the load check)", detail);
    const pnp_library_t* lib = loader.libraries().front().library;
    if (manifest.file != base_name(library_path))
        return check_result(false, "the manifest describes " + manifest.file + ", not " + base_name(library_path),
                            detail);
    const std::string disagreement = engine::manifest_disagreement(manifest, lib);
    if (!disagreement.empty()) return check_result(false, disagreement, detail);
    // Beyond ids and kinds: every member the loader and the tools read from it.
    const nlohmann::json fresh = engine::manifest_json(lib, manifest.file);
    for (const auto& written : manifest.plugins) {
        for (const auto& p : fresh["plugins"]) {
            if (p["id"] != written.id) continue;
            for (auto it = p.begin(); it != p.end(); ++it)
                if (!written.entry.contains(it.key()) || written.entry[it.key()] != it.value())
                    return check_result(false, "manifest " + path + " is stale: plugin " + written.id + " member \"" +
                                                   it.key() + "\" differs from the library's descriptor (rebuild it)",
                                        detail);
        }
    }
    detail["plugins"] = manifest.plugins.size();
    return check_result(true, "", detail);
}

}  // namespace pednav::validate
