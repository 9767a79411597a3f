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

void collect(pn_engine_t* engine, ReplayResult& out) {
    pn_output_t o;
    while (pn_engine_poll(engine, &o) == PN_OK) {
        switch (o.header.type) {
            case PN_REC_POSITION: out.positions.push_back(o.position); break;
            case PN_REC_STRIDE: out.strides.push_back(o.stride); break;
            case PN_REC_STEP: out.steps.push_back(o.step); break;
            case PN_REC_ATTITUDE: out.attitudes.push_back(o.attitude); break;
            case PN_REC_GAIT_PHASE: out.gait_phases.push_back(o.gait_phase); break;
            default: break;
        }
    }
}

std::string error_text(const pn_error_t& err, pn_status_t st) {
    std::string s = pn_status_name(st);
    if (err.where[0]) s += std::string(" at ") + err.where;
    if (err.message[0]) s += std::string(": ") + err.message;
    return s;
}

using EnginePtr = std::unique_ptr<pn_engine_t, EngineDeleter>;

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

ReplayResult replay(const ReplayOptions& options, const std::vector<const pn_record_header_t*>& records) {
    ReplayResult result;
    const EnginePtr engine = create_engine(options, result.error);
    if (!engine) return result;
    pn_error_t err{};
    err.struct_size = sizeof err;
    uint64_t mask = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_STEP);
    if (options.keep_attitudes) mask |= PN_REC_MASK(PN_REC_ATTITUDE);
    if (options.keep_gait_phases) mask |= PN_REC_MASK(PN_REC_GAIT_PHASE);
    pn_engine_set_output_mask(engine.get(), mask);
    result.latency_ns = pn_engine_latency_ns(engine.get());
    pn_status_t st = pn_engine_set_start(engine.get(), options.start_enu_m, options.heading_deg, &err);
    if (PN_FAILED(st) && st != PN_E_UNSUPPORTED) result.warnings.push_back("start not applied: " + error_text(err, st));

    const size_t total = records.size();
    // A file of bad records must not print one warning per record: the first
    // few are listed, the rest counted in one line.
    constexpr size_t kListedRefusals = 10;
    size_t refused = 0;
    for (size_t i = 0; i < total; ++i) {
        st = pn_engine_push(engine.get(), records[i], &err);
        if (st == PN_E_BAD_STATE && stopped(engine.get())) {  // a stage's policy stopped the pipeline
            result.warnings.push_back("record " + std::to_string(i) + ": " + error_text(err, st) + "; the " +
                                      std::to_string(total - i) + " records from here on were not processed");
            result.stopped = true;
            break;
        }
        if (PN_FAILED(st) && ++refused <= kListedRefusals)
            result.warnings.push_back("record " + std::to_string(i) + ": " + error_text(err, st));
        if ((i & 1023) == 1023) {
            collect(engine.get(), result);
            if (options.progress) options.progress(i + 1, total, options.progress_user);
        }
    }
    if (refused > kListedRefusals)
        result.warnings.push_back(std::to_string(refused - kListedRefusals) + " more records refused (" +
                                  std::to_string(refused) + " of " + std::to_string(total) + " in all)");
    if (!result.stopped) {
        st = pn_engine_flush(engine.get(), &err);
        if (PN_FAILED(st)) result.warnings.push_back("flush: " + error_text(err, st));
        result.stopped = st == PN_E_BAD_STATE && stopped(engine.get());
    }
    collect(engine.get(), result);
    if (options.progress) options.progress(total, total, options.progress_user);
    result.describe_json = describe(engine.get());
    result.has_origin = pn_engine_get_origin(engine.get(), &result.origin) == PN_OK;
    const auto d = nlohmann::json::parse(result.describe_json, nullptr, false);
    if (!d.is_discarded()) result.plugin_failures = d["counters"].value("plugin_failures", uint64_t{0});
    return result;
}

}  // namespace pednav
