// SPDX-License-Identifier: Apache-2.0
#include "engine_run.hpp"

#include <cstring>

namespace pednav::validate {

namespace {

pn_error_t fresh_error() {
    pn_error_t e;
    std::memset(&e, 0, sizeof e);
    e.struct_size = sizeof e;
    return e;
}

std::string text_of(pn_status_t status, const pn_error_t& err) {
    std::string t = pn_status_name(status);
    if (err.where[0]) t += std::string(" at ") + err.where;
    if (err.message[0]) t += std::string(": ") + err.message;
    return t;
}

}  // namespace

EngineRun::EngineRun(const nlohmann::json& config, const std::vector<std::string>& plugin_dirs)
    : err_(fresh_error()), config_text_(config.dump()), dirs_(plugin_dirs) {
    std::vector<const char*> dir_ptrs;
    for (const auto& d : dirs_) dir_ptrs.push_back(d.c_str());
    pn_engine_create_info_t info;
    std::memset(&info, 0, sizeof info);
    info.abi_version = PN_ABI_VERSION;
    info.struct_size = sizeof info;
    info.config_json = config_text_.c_str();
    info.config_len = config_text_.size();
    info.plugin_dirs = dir_ptrs.data();
    info.plugin_dir_count = static_cast<uint32_t>(dir_ptrs.size());
    info.log = &on_log;
    info.log_user = this;
    info.output_queue_capacity = 4096;  // polled after every push
    status_ = pn_engine_create(&info, &engine_, &err_);
    if (engine_) {
        const uint64_t all = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) | PN_REC_MASK(PN_REC_STEP) |
                             PN_REC_MASK(PN_REC_ATTITUDE) | PN_REC_MASK(PN_REC_GAIT_PHASE);
        pn_engine_set_output_mask(engine_, all);
    }
}

EngineRun::~EngineRun() { destroy(); }

void EngineRun::destroy() {
    if (!engine_) return;
    phase_ = "destroy";
    pn_engine_destroy(engine_);
    engine_ = nullptr;
}

std::string EngineRun::error_text() const { return text_of(status_, err_); }

void EngineRun::on_log(void* user, int32_t level, const char* source, const char* msg) {
    auto* self = static_cast<EngineRun*>(user);
    self->log_.push_back({self->phase_, level, source ? source : "", msg ? msg : ""});
}

void EngineRun::drain(std::vector<OutputBytes>& outputs) {
    pn_output_t o;
    while (pn_engine_poll(engine_, &o) == PN_OK)
        outputs.emplace_back(reinterpret_cast<const char*>(&o), o.header.struct_size);
}

std::string EngineRun::run(const std::vector<const pn_record_header_t*>& records, std::vector<OutputBytes>& outputs) {
    if (!engine_) return "no engine: " + error_text();
    pn_error_t err = fresh_error();
    phase_ = "process";
    for (size_t i = 0; i < records.size(); ++i) {
        const pn_status_t s = pn_engine_push(engine_, records[i], &err);
        if (s != PN_OK) return "push of input record " + std::to_string(i) + " failed: " + text_of(s, err);
        drain(outputs);
    }
    phase_ = "flush";
    const pn_status_t s = pn_engine_flush(engine_, &err);
    drain(outputs);
    if (s != PN_OK) return "flush failed: " + text_of(s, err);
    return {};
}

std::string EngineRun::reset() {
    if (!engine_) return "no engine: " + error_text();
    pn_error_t err = fresh_error();
    phase_ = "reset";
    const pn_status_t s = pn_engine_reset(engine_, &err);
    return s == PN_OK ? std::string() : "reset failed: " + text_of(s, err);
}

std::vector<std::string> EngineRun::misbehaving() const {
    std::vector<std::string> lines;
    for (const auto& l : log_)
        if (l.level >= 2 && l.message.find("misbehaving") != std::string::npos)
            lines.push_back(l.source + ": " + l.message);
    return lines;
}

}  // namespace pednav::validate
