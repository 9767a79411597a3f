// SPDX-License-Identifier: Apache-2.0
// pednav report: run every shared recording that has a ground truth and every
// built-in simulated walk through the mount presets, score each, and write a
// markdown accuracy table (per walk, and percentiles across walks per mount),
// the same as JSON, and one SVG per walk; or, with --suite, print one of the
// foot pipeline's own tables (report_suites.hpp).
#pragma once

#include <string>
#include <vector>

// args exclude the word "report". Returns the process exit status.
int pednav_cmd_report(const std::vector<std::string>& args);
// Its usage text (pednav report --help).
extern const char* const pednav_cmd_report_usage;
