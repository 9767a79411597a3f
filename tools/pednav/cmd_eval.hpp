// SPDX-License-Identifier: Apache-2.0
// pednav eval: score a track CSV against a ground truth (docs/metrics.md).
#pragma once

#include <string>
#include <vector>

// args exclude the word "eval". Returns the process exit status.
int pednav_cmd_eval(const std::vector<std::string>& args);
// Its usage text (pednav eval --help).
extern const char* const pednav_cmd_eval_usage;
