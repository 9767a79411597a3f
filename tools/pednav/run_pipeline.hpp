// SPDX-License-Identifier: Apache-2.0
// What `pednav run` and `pednav demo` share: load a preset or config file,
// replay records through the engine with a progress bar, print a summary.
#pragma once

#include <string>
#include <vector>

#include <pednav_engine/replay.hpp>

namespace pednav::cli {

// The config text: `config_path` if given, else the preset of `mount`.
std::string load_config(const std::string& config_path, const std::string& mount);

// A progress bar on stderr: done of total (records, bytes).
void progress_bar(size_t done, size_t total, void* unused);

// Replays with a progress bar on stderr when it is a terminal.
ReplayResult run_with_progress(ReplayOptions options, const std::vector<const pn_record_header_t*>& records);

}  // namespace pednav::cli
