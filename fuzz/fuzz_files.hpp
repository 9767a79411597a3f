// SPDX-License-Identifier: Apache-2.0
// The fuzz input as files: the readers take a path, so each input is written
// to a file of this process's own folder under $TMPDIR (or /tmp), and inputs
// that stand for several files are split at a separator line.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pednav::fuzz {

// The line that separates the parts of an input standing for several files
// (a column map and its data, the two files of a senslogs recording, the five
// of a rairyuu map). The seed corpus uses it as written here.
constexpr std::string_view kPartSeparator = "\n----8<----\n";

// This process's folder for fuzz files (created on first use).
const std::string& work_dir();

// Writes `bytes` to work_dir()/name (replacing it) and returns the path.
std::string write_work_file(const std::string& name, std::string_view bytes);

// The input cut at each kPartSeparator, at most `max_parts` parts (the last
// one keeps any further separators); missing parts are empty.
std::vector<std::string_view> split_parts(const uint8_t* data, size_t size, size_t max_parts);

}  // namespace pednav::fuzz
