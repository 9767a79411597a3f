// SPDX-License-Identifier: Apache-2.0
#include "run_pipeline.hpp"

#include <unistd.h>

#include <cstdio>

#include "cli_common.hpp"

namespace pednav::cli {

std::string load_config(const std::string& config_path, const std::string& mount) {
    if (!config_path.empty()) return read_text_file(config_path);
    const std::string preset = default_config_dir() + "/" + mount + ".json";
    try {
        return read_text_file(preset);
    } catch (const std::exception&) {
        throw std::runtime_error("no preset for mount " + mount + " (looked for " + preset +
                                 "); give one with --config FILE");
    }
}

namespace {
void progress_bar(size_t done, size_t total, void*) {
    const int width = 40;
    const int filled = total ? static_cast<int>(width * done / total) : width;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled, "",
                 total ? static_cast<int>(100 * done / total) : 100);
    if (done == total) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}
}  // namespace

ReplayResult run_with_progress(ReplayOptions options, const std::vector<const pn_record_header_t*>& records) {
    if (isatty(2) && records.size() > 100000) options.progress = &progress_bar;
    return replay(options, records);
}

}  // namespace pednav::cli
