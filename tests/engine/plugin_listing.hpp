// SPDX-License-Identifier: Apache-2.0
// Helpers for the loading tests: pn_plugins_describe parsed, which libraries
// the process has open, and the marks the lazy fixtures leave when opened.
#pragma once

#include <dlfcn.h>

#include <cstdlib>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>
#include <nlohmann/json.hpp>

namespace pednav::test {

// pn_plugins_describe over `dirs`, parsed; null when it fails.
inline nlohmann::json list_plugins(const std::vector<std::string>& dirs, uint32_t flags) {
    std::vector<const char*> ptrs;
    for (const auto& d : dirs) ptrs.push_back(d.c_str());
    size_t size = 0;
    if (pn_plugins_describe(ptrs.data(), static_cast<uint32_t>(ptrs.size()), flags, nullptr, 0, &size,
                            nullptr) != PN_E_INVALID_ARGUMENT ||
        size == 0)
        return nullptr;
    std::string text(size, '\0');
    if (pn_plugins_describe(ptrs.data(), static_cast<uint32_t>(ptrs.size()), flags, &text[0], size, &size,
                            nullptr) != PN_OK)
        return nullptr;
    text.resize(size - 1);
    return nlohmann::json::parse(text);
}

// Whether the library at `path` is loaded in this process (opens nothing).
inline bool is_loaded(const std::string& path) {
    void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD);
    if (h) dlclose(h);
    return h != nullptr;
}

// The ten lazy fixtures, "lazy_a1" .. "lazy_b5".
inline std::vector<std::string> lazy_names() {
    std::vector<std::string> names;
    for (const char* dir : {"a", "b"})
        for (int n = 1; n <= 5; ++n) names.push_back(std::string("lazy_") + dir + std::to_string(n));
    return names;
}

// Set by the initializer of a lazy fixture library when it is opened.
inline bool marked(const std::string& name) {
    return std::getenv(("PEDNAV_TEST_OPENED_" + name).c_str()) != nullptr;
}
inline void clear_marks() {
    for (const auto& n : lazy_names()) unsetenv(("PEDNAV_TEST_OPENED_" + n).c_str());
}

// The entry of describe's `member` array whose "path" ends with `file`, or null.
inline nlohmann::json entry_ending(const nlohmann::json& d, const char* member, const std::string& file) {
    for (const auto& e : d.at(member)) {
        const std::string p = e.at("path").get<std::string>();
        if (p.size() >= file.size() && p.compare(p.size() - file.size(), file.size(), file) == 0) return e;
    }
    return nullptr;
}

}  // namespace pednav::test
