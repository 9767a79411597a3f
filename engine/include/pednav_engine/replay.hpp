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

#include <pednav/pn_engine.h>
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
    std::vector<std::string> warnings;     // input rows rejected, then what the engine kept of its warnings
                                           // (plugins' warning-level logs, misbehaviour), and their count
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

// Receives a session's outputs as they are polled.
class OutputHandler {
public:
    virtual ~OutputHandler() = default;
    virtual void on_output(const pn_output_t& output) = 0;
    // After each round of polling: every 1024 records pushed, and at the end.
    virtual void on_polled() {}
};

// replay() a block of records at a time: the same engine calls, warnings and
// outputs, for an input read as it goes (io::RecordStream).
class ReplaySession {
public:
    // Creates the engine; result().error says why when it could not be (then ok() is false).
    // Outputs go to `handler`, or into result() when it is null.
    explicit ReplaySession(const ReplayOptions& options, OutputHandler* handler = nullptr);
    ~ReplaySession();
    ReplaySession(const ReplaySession&) = delete;
    ReplaySession& operator=(const ReplaySession&) = delete;

    bool ok() const { return engine_ != nullptr; }
    // Pushes the next records (time order). Once a stage's failure policy has
    // stopped the pipeline they are only counted; false from then on.
    bool push(const pn_record_header_t* const* records, size_t count);
    // The total given to options.progress (records pushed, of this many).
    void set_progress_total(size_t records) { progress_total_ = records; }
    // Flushes the engine, polls the last outputs and completes result().
    ReplayResult& finish();
    ReplayResult& result() { return result_; }

private:
    void collect();

    ReplayOptions options_;
    OutputHandler* handler_;
    ReplayResult result_;
    pn_engine_t* engine_ = nullptr;
    size_t pushed_ = 0;           // records given to push(), pushed or not
    size_t refused_ = 0;
    size_t stopped_at_ = 0;       // the record the pipeline stopped at
    size_t stop_warning_ = 0;     // its warning, completed by finish()
    std::string stop_error_;
    size_t progress_total_ = 0;
    bool finished_ = false;
};

// Builds the engine for `options` (config checked, plugins loaded and
// created) and tears it down: what replay() would stop on, or "" when none.
std::string config_problem(const ReplayOptions& options);

}  // namespace pednav
