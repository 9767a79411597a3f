// The object behind pn_engine_t: loads plugins, builds the pipeline of the
// configured mount, validates app inputs, and describes itself.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pednav/pn_engine.h>

#include "config.hpp"
#include "loader.hpp"
#include "scheduler.hpp"

namespace pednav::engine {

class Engine {
public:
    // Throws ConfigProblem (status, where, message) when the engine cannot be built.
    explicit Engine(const pn_engine_create_info_t& info);
    ~Engine();

    pn_status_t push(const pn_record_header_t* record, pn_error_t* err);
    pn_status_t flush(pn_error_t* err);
    pn_status_t reset(pn_error_t* err);
    pn_status_t set_start(const double pos_enu_m[3], double heading_deg, pn_error_t* err);

    Scheduler& scheduler() { return *scheduler_; }
    const Scheduler& scheduler() const { return *scheduler_; }
    std::string describe_json() const;

    void log(int32_t level, const char* source, const char* msg) const;

private:
    pn_status_t check_input(const pn_record_header_t* record, pn_error_t* err);
    // PN_OK, or the stage failure of the last push or flush, logged and in *err.
    pn_status_t stage_failure_status(pn_error_t* err) {
        return scheduler_->has_failure() ? report_stage_failure(err) : PN_OK;
    }
    pn_status_t report_stage_failure(pn_error_t* err);  // out of line: not on the per-sample path

    std::unique_ptr<Loader> loader_;
    EngineConfig config_;
    std::unique_ptr<Scheduler> scheduler_;
    pn_log_fn log_ = nullptr;
    void* log_user_ = nullptr;
    int64_t last_t_ns_[PN_REC_TYPE_COUNT];
    int64_t last_any_t_ns_ = INT64_MIN;
    uint64_t rejected_inputs_ = 0;
};

// Fills a caller's pn_error_t (if any).
void set_error(pn_error_t* err, pn_status_t code, const std::string& where, const std::string& message,
               int32_t detail = 0);

}  // namespace pednav::engine
