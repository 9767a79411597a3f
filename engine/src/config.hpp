// SPDX-License-Identifier: Apache-2.0
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

// What the engine does when a stage fails (docs/config.md, "Plugin failures").
enum class OnFailure {
    reset,  // a failure that leaves the instance suspect (PN_E_NUMERIC, PN_E_INTERNAL) resets it; the pipeline goes on
    stop,   // the first failure stops the pipeline until pn_engine_reset
};
enum class OverBudget { warn, stop };

struct StageConfig {
    Role role;
    std::string plugin_id;
    std::string params_json;  // compact JSON object
    std::string pointer;      // "/pipelines/foot/step_detector"
    OnFailure on_failure = OnFailure::reset;
    double call_budget_ms = 0.0;  // wall time one call may take; 0 = no budget
    OverBudget over_budget = OverBudget::warn;
};

struct EngineConfig {
    std::string mount;               // one of kMounts
    double imu_rate_hz = 0.0;        // nominal, 0 = unknown
    std::vector<StageConfig> stages; // of the selected mount, in role order

    // "origin": a fixed geodetic origin, or the accuracy a GNSS fix needs to
    // become the origin when none is given (0 = never).
    bool has_origin = false;
    pn_geo_point_t origin{0.0, 0.0, 0.0};
    double origin_fix_max_h_accuracy_m = 10.0;

    // "map": a map file the engine reads and gives the map matcher at create.
    std::string map_path;            // empty: none
    std::string map_format = "pednav.map/1";
};

// The mounts a config may name, in the order the docs list them.
constexpr const char* kMounts[] = {"foot", "chest", "handheld", "waist"};

// Thrown with the status, the JSON pointer of the key at fault and a message.
struct ConfigProblem {
    pn_status_t status;
    std::string where;
    std::string message;
};

// Parses the document. Throws ConfigProblem.
EngineConfig parse_config(const std::string& text);

}  // namespace pednav::engine
