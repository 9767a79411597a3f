// SPDX-License-Identifier: Apache-2.0
#include <pednav_engine/replay.hpp>

#include <cstring>
#include <memory>

#include <nlohmann/json.hpp>
#include <pednav/pn_engine.h>

#include "pednav_strict_json/strict_json.hpp"

namespace pednav {

namespace {

struct EngineDeleter {
    void operator()(pn_engine_t* e) const { pn_engine_destroy(e); }
};

std::string describe(const pn_engine_t* engine) {
    size_t size = 0;
    pn_engine_describe(engine, nullptr, 0, &size);
    std::string text(size, '\0');
    if (size && pn_engine_describe(engine, text.data(), size, &size) == PN_OK) text.resize(size - 1);
    return text;
}

// Whether a stage's failure policy stopped the pipeline (pn_engine_describe).
bool stopped(const pn_engine_t* engine) {
    const auto d = nlohmann::json::parse(describe(engine), nullptr, false);
    return !d.is_discarded() && d["pipeline"].value("stopped", false);
}

std::string error_text(const pn_error_t& err, pn_status_t st) {
    std::string s = pn_status_name(st);
    if (err.where[0]) s += std::string(" at ") + err.where;
    if (err.message[0]) s += std::string(": ") + err.message;
    return s;
}

using EnginePtr = std::unique_ptr<pn_engine_t, EngineDeleter>;

// Outputs kept in a ReplayResult.
class KeepOutputs : public OutputHandler {
public:
    explicit KeepOutputs(ReplayResult& out) : out_(out) {}
    void on_output(const pn_output_t& o) override {
        switch (o.header.type) {
            case PN_REC_POSITION: out_.positions.push_back(o.position); break;
            case PN_REC_STRIDE: out_.strides.push_back(o.stride); break;
            case PN_REC_STEP: out_.steps.push_back(o.step); break;
            case PN_REC_ATTITUDE: out_.attitudes.push_back(o.attitude); break;
            case PN_REC_GAIT_PHASE: out_.gait_phases.push_back(o.gait_phase); break;
            default: break;
        }
    }

private:
    ReplayResult& out_;
};

// A file of bad records must not print one warning per record: the first
// few are listed, the rest counted in one line.
constexpr size_t kListedRefusals = 10;

// The engine of `options`, or null with `error` set.
EnginePtr create_engine(const ReplayOptions& options, std::string& error) {
    std::string config = options.config_json;
    if (!options.mount.empty()) {
        nlohmann::json doc;
        try {
            doc = strict_json::parse(config);
        } catch (const strict_json::Error& e) {
            error = std::string("PN_E_INVALID_CONFIG") + (e.pointer.empty() ? "" : " at " + e.pointer) +
                    ": config: " + e.what();
            return nullptr;
        }
        if (!doc.is_object()) {
            error = "PN_E_INVALID_CONFIG: config must be a JSON object";
            return nullptr;
        }
        doc["mount"] = options.mount;
        config = doc.dump();
    }
    std::vector<const char*> dirs;
    for (const auto& d : options.plugin_dirs) dirs.push_back(d.c_str());
    pn_engine_create_info_t info{};
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config.c_str();
    info.plugin_dirs = dirs.data();
    info.plugin_dir_count = static_cast<uint32_t>(dirs.size());
    pn_error_t err{};
    err.struct_size = sizeof err;
    pn_engine_t* raw = nullptr;
    const pn_status_t st = pn_engine_create(&info, &raw, &err);
    if (PN_FAILED(st)) {
        error = error_text(err, st);
        return nullptr;
    }
    return EnginePtr(raw);
}

}  // namespace

std::string config_problem(const ReplayOptions& options) {
    std::string error;
    create_engine(options, error);
    return error;
}

ReplaySession::ReplaySession(const ReplayOptions& options, OutputHandler* handler)
    : options_(options), handler_(handler) {
    EnginePtr engine = create_engine(options, result_.error);
    if (!engine) return;
    engine_ = engine.release();
    pn_error_t err{};
    err.struct_size = sizeof err;
    uint64_t mask = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_STEP);
    if (options.keep_attitudes) mask |= PN_REC_MASK(PN_REC_ATTITUDE);
    if (options.keep_gait_phases) mask |= PN_REC_MASK(PN_REC_GAIT_PHASE);
    pn_engine_set_output_mask(engine_, mask);
    result_.latency_ns = pn_engine_latency_ns(engine_);
    const pn_status_t st = pn_engine_set_start(engine_, options.start_enu_m, options.heading_deg, &err);
    if (PN_FAILED(st) && st != PN_E_UNSUPPORTED) result_.warnings.push_back("start not applied: " + error_text(err, st));
}

ReplaySession::~ReplaySession() {
    if (engine_ != nullptr) pn_engine_destroy(engine_);
}

void ReplaySession::collect() {
    KeepOutputs keep(result_);
    OutputHandler& to = handler_ != nullptr ? *handler_ : keep;
    pn_output_t o;
    while (pn_engine_poll(engine_, &o) == PN_OK) to.on_output(o);
    to.on_polled();
}

bool ReplaySession::push(const pn_record_header_t* const* records, size_t count) {
    if (!ok() || finished_) return false;
    if (result_.stopped) {
        pushed_ += count;
        return false;
    }
    pn_error_t err{};
    err.struct_size = sizeof err;
    for (size_t k = 0; k < count; ++k) {
        const size_t i = pushed_++;
        const pn_status_t st = pn_engine_push(engine_, records[k], &err);
        if (st == PN_E_BAD_STATE && stopped(engine_)) {  // a stage's policy stopped the pipeline
            result_.stopped = true;
            stopped_at_ = i;
            stop_error_ = error_text(err, st);
            stop_warning_ = result_.warnings.size();
            result_.warnings.emplace_back();  // completed by finish(), when the records are counted
            pushed_ += count - k - 1;
            return false;
        }
        if (PN_FAILED(st) && ++refused_ <= kListedRefusals)
            result_.warnings.push_back("record " + std::to_string(i) + ": " + error_text(err, st));
        if ((i & 1023) == 1023) {
            collect();
            if (options_.progress) options_.progress(i + 1, progress_total_, options_.progress_user);
        }
    }
    return true;
}

ReplayResult& ReplaySession::finish() {
    if (!ok() || finished_) return result_;
    finished_ = true;
    if (result_.stopped) {
        result_.warnings[stop_warning_] = "record " + std::to_string(stopped_at_) + ": " + stop_error_ + "; the " +
                                          std::to_string(pushed_ - stopped_at_) +
                                          " records from here on were not processed";
    }
    if (refused_ > kListedRefusals)
        result_.warnings.push_back(std::to_string(refused_ - kListedRefusals) + " more records refused (" +
                                   std::to_string(refused_) + " of " + std::to_string(pushed_) + " in all)");
    if (!result_.stopped) {
        pn_error_t err{};
        err.struct_size = sizeof err;
        const pn_status_t st = pn_engine_flush(engine_, &err);
        if (PN_FAILED(st)) result_.warnings.push_back("flush: " + error_text(err, st));
        result_.stopped = st == PN_E_BAD_STATE && stopped(engine_);
    }
    collect();
    if (options_.progress) options_.progress(progress_total_, progress_total_, options_.progress_user);
    result_.describe_json = describe(engine_);
    result_.has_origin = pn_engine_get_origin(engine_, &result_.origin) == PN_OK;
    const auto d = nlohmann::json::parse(result_.describe_json, nullptr, false);
    if (!d.is_discarded()) {
        result_.plugin_failures = d["counters"].value("plugin_failures", uint64_t{0});
        // What the engine and its plugins warned of (a plugin's log at warning level, a refused
        // output, a full output queue), which no log callback here prints: listed as the engine
        // kept them, with the count of those it did not keep.
        const nlohmann::json& kept = d["warnings"];
        if (kept.is_array())
            for (const auto& w : kept)
                if (w.is_string()) result_.warnings.push_back(w.get<std::string>());
        const uint64_t count = d["counters"].value("warnings", uint64_t{0});
        if (kept.is_array() && count > kept.size())
            result_.warnings.push_back(std::to_string(count - kept.size()) + " more engine warnings not listed (" +
                                       std::to_string(count) + " in all)");
    }
    return result_;
}

ReplayResult replay(const ReplayOptions& options, const std::vector<const pn_record_header_t*>& records) {
    ReplaySession session(options);
    if (!session.ok()) return std::move(session.result());
    session.set_progress_total(records.size());
    session.push(records.data(), records.size());
    return std::move(session.finish());
}

}  // namespace pednav
