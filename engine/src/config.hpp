// The engine config document: which plugin fills each role of the pipeline of
// each mount, with its params. Parsed strictly: an unknown key, a wrong type or
// a missing plugin id is an error naming the key as a JSON pointer.
#pragma once

#include <string>
#include <vector>

#include <pednav/pn_types.h>

namespace pednav::engine {

// Pipeline roles in the order records flow through them.
enum class Role { step_detector = 0, attitude_estimator, position_filter, map_matcher };
constexpr int kRoleCount = 4;
const char* role_name(Role role);

struct StageConfig {
    Role role;
    std::string plugin_id;
    std::string params_json;  // compact JSON object
    std::string pointer;      // "/pipelines/foot/step_detector"
};

struct EngineConfig {
    std::string mount;               // "foot", "chest" or "waist"
    double imu_rate_hz = 0.0;        // nominal, 0 = unknown
    std::vector<StageConfig> stages; // of the selected mount, in role order
};

// Thrown with the status, the JSON pointer of the key at fault and a message.
struct ConfigProblem {
    pn_status_t status;
    std::string where;
    std::string message;
};

// Parses the document. Throws ConfigProblem.
EngineConfig parse_config(const std::string& text);

}  // namespace pednav::engine
