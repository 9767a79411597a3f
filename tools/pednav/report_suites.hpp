// SPDX-License-Identifier: Apache-2.0
// pednav report --suite NAME: the foot pipeline's own tables (the foot issue's
// figures, docs/foot-pipeline.md), printed on stdout, one line per walk.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pednav::cli {

struct FootSuiteSetup {
    std::string preset_json;  // configs/foot.json
    std::string detector;     // "shoe" or "multicondition", named on the first line of some suites
    nlohmann::json patch;     // the detector's patch with --patch merged in
    std::string data_dir;     // the shared recordings
    std::vector<std::string> plugin_dirs;
};

// full (the simulated walks at 400 Hz, then every foot recording), quick (the
// xio and koroglu recordings), sim (the simulated walks at 100, 200 and
// 400 Hz), sweep (the corridor loop over gaits, mountings and rates), tables
// (the koroglu paper's tables, ZUPT only and with ZARU), hupt (HUPT against
// ZUPT only), clip (the xio loops with a clipped gyro).
const std::vector<std::string>& foot_suite_names();
// Whether the suite reads the shared recordings.
bool foot_suite_reads_recordings(const std::string& suite);
// Runs and prints one suite; throws std::runtime_error when a walk fails.
void run_foot_suite(const std::string& suite, const FootSuiteSetup& setup);

}  // namespace pednav::cli
