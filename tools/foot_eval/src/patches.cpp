// SPDX-License-Identifier: Apache-2.0
#include <pednav_foot_eval/patches.hpp>

#include <stdexcept>

namespace pednav::foot_eval {

nlohmann::json detector_patch(const std::string& which) {
    nlohmann::json p = nlohmann::json::object();
    if (which == "multicondition") {
        p["pipelines"]["foot"]["step_detector"] = {{"plugin", "org.pednav.foot.stance.multicondition"},
                                                   {"params", nlohmann::json::object()}};
    } else if (which != "shoe") {
        throw std::runtime_error("unknown detector '" + which + "' (shoe or multicondition)");
    }
    return p;
}

nlohmann::json ekf_patch(const nlohmann::json& params) {
    nlohmann::json p;
    p["pipelines"]["foot"]["position_filter"]["params"] = params;
    return p;
}

nlohmann::json with_gyro_range(const nlohmann::json& patch, double range_radps) {
    nlohmann::json p = patch;
    const nlohmann::json::json_pointer range("/pipelines/foot/attitude_estimator/params/gyro_range_radps");
    if (range_radps > 0 && !p.contains(range)) p[range] = range_radps;
    return p;
}

}  // namespace pednav::foot_eval
