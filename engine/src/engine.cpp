// SPDX-License-Identifier: Apache-2.0
#include "engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>

#include "params_schema.hpp"
#include "pipeline_check.hpp"
#include "record_checks.hpp"
#include "scheduler_store.hpp"

namespace pednav::engine {

void set_error(pn_error_t* err, pn_status_t code, const std::string& where, const std::string& message,
               int32_t detail) {
    if (!err) return;
    // Write only what fits in the caller's struct (an older, smaller pn_error_t).
    const size_t size = std::min<size_t>(err->struct_size, sizeof(pn_error_t));
    auto fits = [&](size_t offset, size_t bytes) { return size >= offset + bytes; };
    if (fits(offsetof(pn_error_t, code), sizeof err->code)) err->code = code;
    if (fits(offsetof(pn_error_t, detail), sizeof err->detail)) err->detail = detail;
    auto text = [&](size_t offset, size_t capacity, char* dst, const std::string& src) {
        if (size <= offset) return;
        std::snprintf(dst, std::min(capacity, size - offset), "%s", src.c_str());
    };
    text(offsetof(pn_error_t, where), sizeof err->where, err->where, where);
    text(offsetof(pn_error_t, message), sizeof err->message, err->message, message);
}

namespace {

Role role_for_kind(pnp_kind_t kind) {
    switch (kind) {
        case PNP_KIND_STEP_DETECTOR: return Role::step_detector;
        case PNP_KIND_ATTITUDE_ESTIMATOR: return Role::attitude_estimator;
        case PNP_KIND_POSITION_FILTER: return Role::position_filter;
        default: return Role::map_matcher;
    }
}

std::string available_ids(const Loader& loader, Role role) {
    std::string list;
    for (const auto& p : loader.plugins())
        if (role_for_kind(p.kind) == role) list += (list.empty() ? "" : ", ") + p.id;
    return list.empty() ? "none" : list;
}

std::string config_text(const pn_engine_create_info_t& info) {
    return info.config_len ? std::string(info.config_json, info.config_len)
                           : std::string(info.config_json ? info.config_json : "");
}

}  // namespace

Engine::Engine(const pn_engine_create_info_t& info)
    : diagnostics_(info.log, info.log_user), loader_(std::make_unique<Loader>()) {
    for (auto& t : last_t_ns_) t = INT64_MIN;
    for (pn_record_type_t t = 0; t < PN_REC_TYPE_COUNT; ++t) input_values_ok_[t] = values_check_for(t);
    if (info.output_queue_capacity > PN_OUTPUT_QUEUE_MAX)
        throw ConfigProblem{PN_E_INVALID_ARGUMENT, "create_info",
                            "output_queue_capacity " + std::to_string(info.output_queue_capacity) +
                                " is above PN_OUTPUT_QUEUE_MAX (" + std::to_string(PN_OUTPUT_QUEUE_MAX) + ")"};
    config_ = parse_config(config_text(info));
    if (config_.has_origin) origin_.set(config_.origin, GeoOrigin::Source::config);

    // Manifests first; then only the libraries of the configured plugin ids are opened.
    for (uint32_t i = 0; i < info.plugin_dir_count; ++i)
        if (info.plugin_dirs && info.plugin_dirs[i]) loader_->scan_directory(info.plugin_dirs[i]);
    for (uint32_t i = 0; i < info.static_library_count; ++i)
        if (info.static_libraries) loader_->add_static_library(info.static_libraries[i], "<static:" + std::to_string(i) + ">");
    std::vector<std::string> wanted_ids;
    for (const StageConfig& sc : config_.stages) wanted_ids.push_back(sc.plugin_id);
    loader_->open_for(wanted_ids);
    for (const auto& r : loader_->rejected())
        diagnostics_.log(PNP_LOG_WARN, "engine", ("rejected plugin file " + r.path + ": " + r.reason).c_str());
    for (const auto& w : loader_->warnings())
        diagnostics_.log(PNP_LOG_WARN, "engine", (w.path + ": " + w.message).c_str());

    std::vector<std::unique_ptr<Stage>> stages = plan_stages();
    check_pipeline_needs(stages);
    create_instances(stages);
    scheduler_ = std::make_unique<Scheduler>(std::move(stages), info.output_queue_capacity, diagnostics_);
    if (!config_.map_path.empty()) load_config_map();
}

// One Stage per configured role, with its descriptor; no plugin code runs yet.
std::vector<std::unique_ptr<Stage>> Engine::plan_stages() {
    std::vector<std::unique_ptr<Stage>> stages;
    for (const StageConfig& sc : config_.stages) {
        const AvailablePlugin* p = loader_->find(sc.plugin_id);
        if (!p && (sc.plugin_id.find('/') != std::string::npos || sc.plugin_id.find(".so") != std::string::npos))
            throw ConfigProblem{PN_E_NOT_FOUND, sc.pointer + "/plugin",
                                "\"" + sc.plugin_id + "\" looks like a file path: a config names plugin ids, and "
                                "libraries load only from the plugin directories the app gives (pednav plugins lists "
                                "the ids)"};
        if (!p) {
            const std::string why = loader_->rejection_for(sc.plugin_id);
            throw ConfigProblem{PN_E_NOT_FOUND, sc.pointer + "/plugin",
                                "plugin " + sc.plugin_id + " is not available: " +
                                    (why.empty() ? "no library found provides it (" + std::string(role_name(sc.role)) +
                                                       " plugins found: " + available_ids(*loader_, sc.role) + ")"
                                                 : "its library was rejected: " + why)};
        }
        const pnp_descriptor_t* d = p->descriptor;
        if (role_for_kind(d->kind) != sc.role)
            throw ConfigProblem{PN_E_INVALID_CONFIG, sc.pointer + "/plugin",
                                "plugin " + sc.plugin_id + " is a " + kind_name(d->kind) + ", not a " + role_name(sc.role)};
        auto stage = std::make_unique<Stage>();
        stage->role = sc.role;
        stage->instance_name = config_.mount + "/" + role_name(sc.role);
        stage->plugin_id = sc.plugin_id;
        stage->pointer = sc.pointer;
        stage->descriptor = d;
        stage->ops = d->ops;
        stage->on_failure = sc.on_failure;
        stage->call_budget_ns = static_cast<int64_t>(sc.call_budget_ms * 1e6);
        stage->over_budget = sc.over_budget;
        stage->host_context.source = stage->instance_name;
        stage->host_context.diagnostics = &diagnostics_;
        stage->host_context.origin = &origin_;
        init_host(&stage->host_context);
        stages.push_back(std::move(stage));
    }
    return stages;
}

// Initialises each library (once) and creates the instances in role order.
// On a throw the stages, and so the instances made so far, are destroyed.
void Engine::create_instances(std::vector<std::unique_ptr<Stage>>& stages) {
    for (size_t k = 0; k < stages.size(); ++k) {
        Stage& stage = *stages[k];
        const StageConfig& sc = config_.stages[k];
        const AvailablePlugin* p = loader_->find(sc.plugin_id);
        const LibraryFile& lib = loader_->libraries()[p->library_index];
        pn_error_t err{};
        err.struct_size = sizeof err;
        const pnp_host_t* library_host = nullptr;  // what the library's init gets, if it runs now
        if (!lib.init_done) {
            auto host = std::make_unique<HostContext>();
            host->source = lib.library->id && *lib.library->id ? lib.library->id : lib.path;
            host->diagnostics = &diagnostics_;
            host->origin = &origin_;
            init_host(host.get());
            library_host = &host->host;
            library_hosts_.push_back(std::move(host));
        }
        if (PN_FAILED(loader_->ensure_init(p->library_index, library_host, &err)))
            throw ConfigProblem{err.code ? err.code : PN_E_INTERNAL, sc.pointer + "/plugin",
                                "library of " + sc.plugin_id + " refused to initialise: " + err.message};
        pnp_create_info_t ci{};
        ci.abi_version = PN_ABI_VERSION;
        ci.struct_size = sizeof ci;
        ci.params_json = sc.params_json.c_str();
        ci.params_len = static_cast<uint32_t>(sc.params_json.size());
        ci.instance_name = stage.instance_name.c_str();
        ci.mount = config_.mount.c_str();
        ci.imu_rate_hz = config_.imu_rate_hz;
        check_params_against_schema(*stage.descriptor, sc);
        const pn_status_t st = stage.descriptor->create(stage.descriptor, &stage.host_context.host, &ci, &stage.self, &err);
        if (PN_FAILED(st) || !stage.self) {
            const std::string inner = err.where;
            const char* reason = err.message[0] ? err.message : "no reason given";
            if (PN_FAILED(st) && st != PN_E_INTERNAL && st != PN_E_OUT_OF_MEMORY)
                throw ConfigProblem{st, sc.pointer + "/params" + (inner.rfind('/', 0) == 0 ? inner : std::string()),
                                    sc.plugin_id + " rejected its params: " + reason};
            throw ConfigProblem{PN_FAILED(st) ? st : PN_E_INTERNAL, sc.pointer + "/plugin",
                                sc.plugin_id + " (" + stage.instance_name + ") failed in create" +
                                    (PN_FAILED(st) ? std::string(": ") + reason : ": it returned no instance")};
        }
    }
}

Engine::~Engine() {
    scheduler_.reset();  // instances before libraries
    loader_.reset();
}

pn_status_t Engine::check_input(const pn_record_header_t* r, pn_error_t* err) {
    if (!r) {
        set_error(err, PN_E_INVALID_ARGUMENT, "input", "record pointer is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    if (r->type >= PN_REC_TYPE_COUNT || !(kInputTypes & PN_REC_MASK(r->type))) {  // range first: no shift past 63
        set_error(err, PN_E_INVALID_ARGUMENT, "input",
                  "record type " + std::to_string(r->type) + " is not an input type (imu, mag, baro, gnss)");
        return PN_E_INVALID_ARGUMENT;
    }
    if (r->struct_size < min_record_size(r->type) || r->struct_size > PN_RECORD_MAX_SIZE) {
        set_error(err, PN_E_INVALID_ARGUMENT, "input",
                  std::string(record_type_name(r->type)) + " record has struct_size " + std::to_string(r->struct_size) +
                      ", expected at least " + std::to_string(min_record_size(r->type)));
        return PN_E_INVALID_ARGUMENT;
    }
    if (r->t_ns > kMaxAbsTimeNs || r->t_ns < -kMaxAbsTimeNs) {
        char msg[160];
        std::snprintf(msg, sizeof msg, "%s sample at t=%.6g s is outside the engine's clock range of +-2^62 ns (%.4g s)",
                      record_type_name(r->type), static_cast<double>(r->t_ns) * 1e-9,
                      static_cast<double>(kMaxAbsTimeNs) * 1e-9);
        set_error(err, PN_E_INVALID_ARGUMENT, "input", msg);
        return PN_E_INVALID_ARGUMENT;
    }
    const bool in_order = r->t_ns >= last_any_t_ns_ && r->t_ns > last_t_ns_[r->type];
    if (in_order && record_values_ok(r)) return PN_OK;
    const ValueProblem bad = find_value_problem(r);
    char at[64];
    std::snprintf(at, sizeof at, " at t=%.6f s", static_cast<double>(r->t_ns) * 1e-9);
    if (bad) {
        set_error(err, PN_E_NUMERIC, "input",
                  std::string(record_type_name(r->type)) + " sample" + at + ": " + describe(bad));
        return PN_E_NUMERIC;
    }
    const int64_t prev = std::max(last_any_t_ns_, last_t_ns_[r->type]);
    char msg[160];
    std::snprintf(msg, sizeof msg, "%s sample%s is not after the previous sample at t=%.6f s",
                  record_type_name(r->type), at, static_cast<double>(prev) * 1e-9);
    set_error(err, PN_E_OUT_OF_ORDER, "input", msg);
    return PN_E_OUT_OF_ORDER;
}

pn_status_t Engine::report_stage_failure(pn_error_t* err) {
    StageFailure f = scheduler_->take_failure();
    set_error(err, f.status, f.where, f.message);
    return f.status;
}

pn_status_t Engine::report_stopped(pn_error_t* err) const {
    const StageFailure& why = scheduler_->stop_reason();
    set_error(err, PN_E_BAD_STATE, why.where,
              "the pipeline is stopped (pn_engine_reset starts it again): " + why.message);
    return PN_E_BAD_STATE;
}

// What check_input accepts, and that the pipeline runs: the per-sample path.
// check_input describes whatever this refuses.
PEDNAV_ALWAYS_INLINE bool Engine::input_fine(const pn_record_header_t* r) const {
    if (!r || scheduler_->stopped()) return false;
    const pn_record_type_t type = r->type;
    if (type >= PN_REC_TYPE_COUNT || !(kInputTypes & PN_REC_MASK(type))) return false;
    if (r->struct_size < min_record_size(type) || r->struct_size > PN_RECORD_MAX_SIZE) return false;
    const int64_t t = r->t_ns;
    constexpr uint64_t kRange = uint64_t{1} << 63;  // [-2^62, 2^62] shifted to [0, 2^63]
    if (static_cast<uint64_t>(t) + static_cast<uint64_t>(kMaxAbsTimeNs) > kRange) return false;
    return t >= last_any_t_ns_ && t > last_t_ns_[type] && input_values_ok_[type](r);
}

pn_status_t Engine::push(const pn_record_header_t* r, pn_error_t* err) {
    if (!input_fine(r)) {
        if (scheduler_->stopped()) return report_stopped(err);
        const pn_status_t st = check_input(r, err);
        if (PN_FAILED(st)) {
            ++rejected_inputs_;
            return st;
        }
    }
    last_t_ns_[r->type] = r->t_ns;
    last_any_t_ns_ = r->t_ns;
    pushed_ = true;
    if (r->type == PN_REC_GNSS && !origin_.known()) take_origin_from_fix(*reinterpret_cast<const pn_gnss_t*>(r));
    scheduler_->push(r);
    return stage_failure_status(err);
}

// The first fix accurate enough becomes the origin when nothing else gave one.
void Engine::take_origin_from_fix(const pn_gnss_t& fix) {
    const double limit = config_.origin_fix_max_h_accuracy_m;
    if (!(fix.h_accuracy_m > 0.0 && fix.h_accuracy_m <= limit)) return;
    const pn_geo_point_t p{fix.lat_deg, fix.lon_deg, fix.height_m};
    if (!GeoOrigin::valid(p)) return;
    origin_.set(p, GeoOrigin::Source::gnss_fix);
    char msg[160];
    std::snprintf(msg, sizeof msg, "geodetic origin taken from the GNSS fix at t=%.3f s: %.8f, %.8f deg, %.2f m",
                  static_cast<double>(fix.header.t_ns) * 1e-9, p.lat_deg, p.lon_deg, p.height_m);
    diagnostics_.log(PNP_LOG_INFO, "engine", msg);
}

pn_status_t Engine::flush(pn_error_t* err) {
    if (scheduler_->stopped()) return report_stopped(err);
    scheduler_->flush();
    return stage_failure_status(err);
}

pn_status_t Engine::reset(pn_error_t* err) {
    for (auto& t : last_t_ns_) t = INT64_MIN;
    last_any_t_ns_ = INT64_MIN;
    pushed_ = false;
    origin_.forget_derived();
    const pn_status_t st = scheduler_->reset(err);
    if (PN_FAILED(st)) return st;
    return reapply_settings(err);
}

}  // namespace pednav::engine
