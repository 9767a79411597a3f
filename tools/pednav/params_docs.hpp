// SPDX-License-Identifier: Apache-2.0
// Parameter tables generated into Markdown files. A file holds one or more
// blocks
//     <!-- params:begin [id=PREFIX] [level=N] -->
//     ...the output of params_markdown() for those options...
//     <!-- params:end -->
// (id: only plugins whose id starts with PREFIX; level: the heading level of
// each plugin, 4 unless given). `pednav plugins --params --markdown --update
// FILE...` rewrites them; `--check FILE...` lists every difference, naming
// the plugin and the key, and the command that regenerates them.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pednav::cli {

// What `pednav plugins --params` was asked for.
struct ParamsRequest {
    bool params = false;  // --params
    bool markdown = false;
    bool check = false;   // --check FILE...
    bool update = false;  // --update FILE...
    std::vector<std::string> files;
    std::vector<std::string> plugin_dirs;  // given with --plugin-dir, for the regenerate command
    // Any of these options makes `pednav plugins` a parameter listing.
    bool asked() const { return params || markdown || check || update || !files.empty(); }
};

// Prints the listing, or checks or updates the files. Returns the exit code:
// 0, or 1 when a checked file differs (the differences on stderr). Throws
// UsageError for files without --check or --update, or either without files.
int params_command(const nlohmann::json& plugins, const ParamsRequest& request);

// The differences between the blocks of a Markdown text and the generated
// tables, one sentence each ("README.md:120: org.pednav.foot.ekf15 (position_filter),
// swing_propagation_s: default is 0.1 in the file, 0.2 in the schema"); empty
// when they agree. Throws std::runtime_error when the text has no block or a
// block is not closed.
std::vector<std::string> params_docs_differences(const std::string& name, const std::string& text,
                                                 const nlohmann::json& plugins);
// The text with every block regenerated. Throws like params_docs_differences.
std::string params_docs_updated(const std::string& name, const std::string& text,
                                const nlohmann::json& plugins);

}  // namespace pednav::cli
