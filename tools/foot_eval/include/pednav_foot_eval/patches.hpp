// SPDX-License-Identifier: Apache-2.0
// Merge patches of the foot preset (configs/foot.json) that the foot suites
// and tests try; apply them with eval::patched_config.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace pednav::foot_eval {

// Selects the stance detector: "shoe" (the preset's, an empty patch) or
// "multicondition" (with its own defaults). Throws std::runtime_error on any other name.
nlohmann::json detector_patch(const std::string& which);
// Sets the position filter's params.
nlohmann::json ekf_patch(const nlohmann::json& params);
// `patch` with the attitude estimator told the sensor's gyro range (its
// clipping repair), unless the patch sets gyro_range_radps itself (0 = the
// repair off) or `range_radps` is 0 (a sensor that does not clip).
nlohmann::json with_gyro_range(const nlohmann::json& patch, double range_radps);

}  // namespace pednav::foot_eval
