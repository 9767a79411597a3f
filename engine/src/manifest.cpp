// SPDX-License-Identifier: Apache-2.0
#include "manifest.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>

#include "describe.hpp"
#include "loader.hpp"
#include "parsed_text_cache.hpp"

namespace pednav::engine {

namespace {

// A manifest is a few kilobytes; anything this large is not one.
constexpr std::streamoff kMaxManifestBytes = 4 << 20;

[[noreturn]] void malformed(const std::string& path, const std::string& pointer, const std::string& what) {
    throw ManifestError{PN_E_BAD_INPUT,
                        "malformed manifest " + path + ": " + (pointer.empty() ? "" : pointer + ": ") + what};
}

const nlohmann::json& member(const nlohmann::json& obj, const char* key, const std::string& path,
                             const std::string& at) {
    auto it = obj.find(key);
    if (it == obj.end()) malformed(path, at + "/" + key, "missing");
    return *it;
}

std::string string_member(const nlohmann::json& obj, const char* key, const std::string& path,
                          const std::string& at, bool non_empty = false) {
    const nlohmann::json& v = member(obj, key, path, at);
    if (!v.is_string()) malformed(path, at + "/" + key, "must be a string");
    if (non_empty && v.get_ref<const std::string&>().empty())
        malformed(path, at + "/" + key, "must not be empty");
    return v.get<std::string>();
}

void string_array_member(const nlohmann::json& obj, const char* key, const std::string& path,
                         const std::string& at) {
    const nlohmann::json& v = member(obj, key, path, at);
    if (!v.is_array()) malformed(path, at + "/" + key, "must be an array of strings");
    for (size_t i = 0; i < v.size(); ++i)
        if (!v[i].is_string()) malformed(path, at + "/" + key + "/" + std::to_string(i), "must be a string");
}

// "1.0" -> {1, 0}; false unless it is two unsigned integers below 65536.
bool parse_abi_version(const std::string& s, uint32_t& major, uint32_t& minor) {
    const size_t dot = s.find('.');
    if (dot == std::string::npos) return false;
    auto number = [](const std::string& digits, uint32_t& out) {
        if (digits.empty() || digits.size() > 5) return false;
        uint32_t v = 0;
        for (char c : digits) {
            if (c < '0' || c > '9') return false;
            v = v * 10 + static_cast<uint32_t>(c - '0');
        }
        out = v;
        return v <= 0xffff;
    };
    return number(s.substr(0, dot), major) && number(s.substr(dot + 1), minor);
}

ManifestPlugin parse_plugin(const nlohmann::json& p, const std::string& path, const std::string& at) {
    if (!p.is_object()) malformed(path, at, "a plugin must be an object");
    ManifestPlugin mp;
    mp.id = string_member(p, "id", path, at, true);
    const std::string kind = string_member(p, "kind", path, at);
    mp.kind = kind_from_name(kind);
    if (mp.kind == 0)
        malformed(path, at + "/kind",
                  "\"" + kind +
                      "\" is not a plugin kind (step_detector, attitude_estimator, position_filter, "
                      "map_matcher)");
    for (const char* key : {"name", "version", "vendor", "description"}) string_member(p, key, path, at);
    const nlohmann::json& kv = member(p, "kind_version", path, at);
    if (!kv.is_number_unsigned()) malformed(path, at + "/kind_version", "must be an unsigned integer");
    for (const char* key : {"mounts", "features", "consumes", "produces"})
        string_array_member(p, key, path, at);
    member(p, "params_schema", path, at);  // a JSON Schema, or null
    mp.entry = p;
    mp.entry.erase("library");
    return mp;
}

}  // namespace

std::string manifest_path_for(const std::string& library_path) {
    const size_t slash = library_path.find_last_of('/');
    const size_t dot = library_path.find_last_of('.');
    const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return (has_ext ? library_path.substr(0, dot) : library_path) + ".json";
}

Manifest parse_manifest(const std::string& text, const std::string& path) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw ManifestError{PN_E_BAD_INPUT, "malformed manifest " + path + ": not valid JSON: " + e.what()};
    }
    if (!doc.is_object()) malformed(path, "", "a manifest must be a JSON object");
    const std::string format = string_member(doc, "format", path, "");
    if (format != kManifestFormat)
        malformed(path, "/format", "\"" + format + "\" is not \"" + kManifestFormat + "\"");
    Manifest m;
    m.path = path;
    m.file = string_member(doc, "file", path, "", true);
    if (m.file.find('/') != std::string::npos) malformed(path, "/file", "must be a file name, not a path");
    const nlohmann::json& lib = member(doc, "library", path, "");
    if (!lib.is_object()) malformed(path, "/library", "must be an object with \"id\" and \"version\"");
    m.library_id = string_member(lib, "id", path, "/library", true);
    m.library_version = string_member(lib, "version", path, "/library");
    const std::string abi = string_member(doc, "abi_version", path, "");
    if (!parse_abi_version(abi, m.abi_major, m.abi_minor))
        malformed(path, "/abi_version", "\"" + abi + "\" is not MAJOR.MINOR");
    const nlohmann::json& plugins = member(doc, "plugins", path, "");
    if (!plugins.is_array() || plugins.empty()) malformed(path, "/plugins", "must be a non-empty array");
    std::set<std::string> ids;
    for (size_t i = 0; i < plugins.size(); ++i) {
        const std::string at = "/plugins/" + std::to_string(i);
        m.plugins.push_back(parse_plugin(plugins[i], path, at));
        if (!ids.insert(m.plugins.back().id).second)
            malformed(path, at + "/id", "plugin id " + m.plugins.back().id + " is listed twice");
    }
    return m;
}

Manifest read_manifest(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ManifestError{PN_E_IO, "manifest " + path + " cannot be read: " + std::strerror(errno)};
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size > kMaxManifestBytes)
        throw ManifestError{PN_E_BAD_INPUT, "malformed manifest " + path + ": " + std::to_string(size) +
                                                " bytes, more than a manifest can be (" +
                                                std::to_string(kMaxManifestBytes) + ")"};
    in.seekg(0, std::ios::beg);
    std::string text(static_cast<size_t>(size > 0 ? size : 0), '\0');
    in.read(&text[0], static_cast<std::streamsize>(text.size()));
    if (!in) throw ManifestError{PN_E_IO, "manifest " + path + " cannot be read"};
    // Parsed once per process for the same path and text (parsed_text_cache.hpp: a manifest
    // holds its plugins' parameter schemas); the file is read each time, so a
    // rebuilt library's new manifest is seen.
    static ParsedTextCache<Manifest> manifests;
    return *manifests.get(path + '\0' + text,
                          [&](const std::string&) { return parse_manifest(text, path); });
}

nlohmann::json manifest_json(const pnp_library_t* library, const std::string& file) {
    nlohmann::json plugins = nlohmann::json::array();
    for (uint32_t i = 0; i < library->plugin_count; ++i)
        plugins.push_back(describe_plugin(library->plugins[i]));
    return {{"format", kManifestFormat},
            {"file", file},
            {"library",
             {{"id", library->id ? library->id : ""}, {"version", library->version ? library->version : ""}}},
            {"abi_version", std::to_string(PN_ABI_VERSION_MAJOR(library->abi_version)) + "." +
                                std::to_string(PN_ABI_VERSION_MINOR(library->abi_version))},
            {"plugins", plugins}};
}

std::string manifest_disagreement(const Manifest& m, const pnp_library_t* library) {
    std::vector<std::string> diffs;
    const std::string lib_id = library->id ? library->id : "";
    if (lib_id != m.library_id)
        diffs.push_back("library id " + m.library_id + " in the manifest, " + lib_id + " in the library");
    const uint32_t major = PN_ABI_VERSION_MAJOR(library->abi_version);
    if (major != m.abi_major)
        diffs.push_back("ABI major " + std::to_string(m.abi_major) + " in the manifest, " +
                        std::to_string(major) + " in the library");
    std::set<std::string> in_library;
    for (uint32_t i = 0; i < library->plugin_count; ++i) {
        const pnp_descriptor_t* d = library->plugins ? library->plugins[i] : nullptr;
        if (!d || !d->id) continue;  // refused by the descriptor checks, with its own reason
        in_library.insert(d->id);
        const ManifestPlugin* listed = nullptr;
        for (const auto& p : m.plugins) listed = p.id == d->id ? &p : listed;
        if (!listed)
            diffs.push_back(std::string("plugin ") + d->id + " is in the library but not in the manifest");
        else if (listed->kind != d->kind)
            diffs.push_back(std::string("plugin ") + d->id + " is a " + kind_name(listed->kind) +
                            " in the manifest, a " + kind_name(d->kind) + " in the library");
    }
    for (const auto& p : m.plugins)
        if (!in_library.count(p.id))
            diffs.push_back("plugin " + p.id + " is in the manifest but not in the library");
    if (diffs.empty()) return {};
    std::string text = "manifest " + m.path + " disagrees with the library: ";
    for (size_t i = 0; i < diffs.size(); ++i) text += (i ? "; " : "") + diffs[i];
    return text;
}

}  // namespace pednav::engine
