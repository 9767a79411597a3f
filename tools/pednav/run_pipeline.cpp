// SPDX-License-Identifier: Apache-2.0
#include "run_pipeline.hpp"

#include <unistd.h>

#include <cstdio>

#include "cli_common.hpp"
#include "pednav_strict_json/strict_json.hpp"

namespace pednav::cli {

namespace {
// The presets are a few KiB; a config file beyond this is not one.
constexpr size_t kMaxConfigBytes = size_t{16} << 20;
}  // namespace

std::string load_config(const std::string& config_path, const std::string& mount) {
    if (!config_path.empty()) {
        std::string text = read_text_file(config_path);
        if (text.size() > kMaxConfigBytes)
            throw std::runtime_error("config " + config_path + ": " + std::to_string(text.size()) +
                                     " bytes, more than the " + std::to_string(kMaxConfigBytes >> 20) +
                                     " MiB a config may hold");
        // The engine takes a C string and the tools patch the document: both
        // need it free of NUL bytes, duplicate keys and runaway nesting.
        try {
            strict_json::parse(text);
        } catch (const strict_json::Error& e) {
            throw std::runtime_error("config " + config_path + ": " + e.what());
        }
        return text;
    }
    const std::string preset = default_config_dir() + "/" + mount + ".json";
    try {
        return read_text_file(preset);
    } catch (const std::exception&) {
        throw std::runtime_error("no preset for mount " + mount + " (looked for " + preset +
                                 "); give one with --config FILE");
    }
}

void progress_bar(size_t done, size_t total, void*) {
    const int width = 40;
    const int filled = total ? static_cast<int>(width * done / total) : width;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
                 total ? static_cast<int>(100 * done / total) : 100);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}

ReplayResult run_with_progress(ReplayOptions options, const std::vector<const pn_record_header_t*>& records) {
    if (isatty(2) && records.size() > 100000) options.progress = &progress_bar;
    return replay(options, records);
}

}  // namespace pednav::cli
