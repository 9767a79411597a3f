// SPDX-License-Identifier: Apache-2.0
// One engine of the validator: created from a config through the C API, with
// a log callback that keeps every line and the phase it was written in
// (create, process, flush, reset, destroy).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pednav/pn_engine.h>

#include "pednav_validate/output_checks.hpp"

namespace pednav::validate {

struct LogLine {
    std::string phase;
    int32_t level;
    std::string source;
    std::string message;
};

class EngineRun {
public:
    EngineRun(const nlohmann::json& config, const std::vector<std::string>& plugin_dirs);
    ~EngineRun();  // destroy: its log lines are in the phase "destroy" of `log` given to destroy()
    EngineRun(const EngineRun&) = delete;
    EngineRun& operator=(const EngineRun&) = delete;

    bool created() const { return engine_ != nullptr; }
    const pn_error_t& error() const { return err_; }
    pn_status_t status() const { return status_; }
    // "PN_E_INVALID_CONFIG at /pipelines/foot/...: message"
    std::string error_text() const;

    // Pushes every record, polling after each, then flushes. Empty on success,
    // otherwise which call failed and the engine's error.
    std::string run(const std::vector<const pn_record_header_t*>& records, std::vector<OutputBytes>& outputs);
    std::string reset();
    // Destroys the engine now (phase "destroy"); the lines stay readable.
    void destroy();

    const std::vector<LogLine>& log() const { return log_; }
    // Lines at WARN and above that report a contract violation ("misbehaving: ...").
    std::vector<std::string> misbehaving() const;

private:
    static void on_log(void* user, int32_t level, const char* source, const char* msg);
    void drain(std::vector<OutputBytes>& outputs);

    pn_engine_t* engine_ = nullptr;
    pn_error_t err_{};
    pn_status_t status_ = PN_OK;
    std::string phase_ = "create";
    std::vector<LogLine> log_;
    std::string config_text_;
    std::vector<std::string> dirs_;
};

}  // namespace pednav::validate
