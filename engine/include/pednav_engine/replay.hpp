// SPDX-License-Identifier: Apache-2.0
// Runs a whole recording through an engine in one call: the C++ convenience
// used by the CLI, the accuracy tests, the report and the benchmarks. It goes
// through the same C API an app uses (pn_engine.h), so the plugins are the real
// ones loaded by the real loader.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <pednav/pn_types.h>

namespace pednav {

struct ReplayOptions {
    std::string config_json;              // the whole engine config document (configs/foot.json)
    std::vector<std::string> plugin_dirs;  // where the plugin libraries are
    std::string mount;                     // overrides the config's "mount" when non-empty
    double start_enu_m[3] = {0.0, 0.0, 0.0};
    double heading_deg = NAN;              // start heading, clockwise from north; NaN = plugins decide
    bool keep_attitudes = false;           // attitude records are per sample: kept only on request
    bool keep_gait_phases = false;         // likewise
    // Called with (records pushed, records total) now and then; may be empty.
    void (*progress)(size_t done, size_t total, void* user) = nullptr;
    void* progress_user = nullptr;
};

struct ReplayResult {
    std::vector<pn_position_t> positions;  // the pipeline's final positions, per IMU sample
    std::vector<pn_stride_t> strides;      // one per step
    std::vector<pn_step_t> steps;          // step detector events
    std::vector<pn_attitude_t> attitudes;  // when keep_attitudes
    std::vector<pn_gait_phase_t> gait_phases;  // when keep_gait_phases
    std::vector<std::string> warnings;     // input rows rejected, plugin misbehaviour, ...
    std::string error;                     // non-empty when the run stopped early; outputs so far are kept
    uint64_t plugin_failures = 0;          // plugin calls that failed (each also in warnings)
    bool stopped = false;                  // a stage's failure policy stopped the pipeline (the last warning says where)
    int64_t latency_ns = 0;                // pipeline output latency
    std::string describe_json;             // pn_engine_describe() at the end
    bool has_origin = false;               // the engine had a geodetic origin at the end (pn_engine_get_origin)
    pn_geo_point_t origin{0.0, 0.0, 0.0};  // WGS-84 of ENU (0, 0, 0): config, app, map or first good GNSS fix
};

// `records` must be in non-decreasing time order (io::merged_records gives that).
ReplayResult replay(const ReplayOptions& options, const std::vector<const pn_record_header_t*>& records);

// Builds the engine for `options` (config checked, plugins loaded and
// created) and tears it down: what replay() would stop on, or "" when none.
std::string config_problem(const ReplayOptions& options);

}  // namespace pednav
