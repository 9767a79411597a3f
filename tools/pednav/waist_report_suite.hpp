// SPDX-License-Identifier: Apache-2.0
// pednav report --suite waist: the waist pipeline's tables
// (docs/waist-pipeline.md), printed on stdout, one line per walk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pednav::cli {

// The ipol lower-back walks (steps, U-turn, legs with step-length constants
// calibrated leave one subject out against the foot pipeline's legs), then
// the simulated waist walks (loop closure without GNSS, GNSS outages, the
// error with GNSS, stairs), seeds 1 to `seeds`; with `only` not empty,
// only the walks whose name contains it ("ipol", "ipol step models",
// "corridor_loop", "outdoor_indoor", "block_laps", "stairs"). Throws std::runtime_error when
// a walk fails.
void run_waist_suite(const std::string& waist_preset_json, const std::string& foot_preset_json,
                     const std::string& data_dir, const std::vector<std::string>& plugin_dirs,
                     uint64_t seeds = 8, const std::string& only = "");

}  // namespace pednav::cli
