// SPDX-License-Identifier: Apache-2.0
// pednav report --suite chest: the chest and handheld pipelines' tables
// (docs/chest-pipeline.md, "Accuracy"), printed on stdout.
#pragma once

#include <string>
#include <vector>

namespace pednav::cli {

struct ChestSuiteSetup {
    std::string chest_preset_json, handheld_preset_json;  // configs/chest.json, configs/handheld.json
    std::string data_dir;                                 // the shared recordings
    std::vector<std::string> plugin_dirs;
};

// humolire-phone without a map (each preset as is, then calibrated on the
// other walks' landmarks), the biba-chest-xsens routes, the simulated chest
// and handheld walks over three seeds (as is, then calibrated on one other
// walk), and steps at several rates and with jittered sample times. Throws
// std::runtime_error when a walk fails or its files are missing.
void run_chest_suite(const ChestSuiteSetup& setup);

}  // namespace pednav::cli
