// SPDX-License-Identifier: Apache-2.0
// Engine::describe_json: what was loaded, refused and wired, as JSON.
#include <cstring>

#include <nlohmann/json.hpp>

#include "engine.hpp"
#include "describe.hpp"
#include "parsed_text_cache.hpp"
#include "record_checks.hpp"

namespace pednav::engine {

namespace {

nlohmann::json type_names(uint64_t mask) {
    nlohmann::json a = nlohmann::json::array();
    for (pn_record_type_t t = 0; t < 64; ++t)
        if (mask & PN_REC_MASK(t)) a.push_back(record_type_name(t));
    return a;
}

}  // namespace

nlohmann::json describe_plugin(const pnp_descriptor_t* d) {
    nlohmann::json p = {{"id", d->id},
                        {"name", d->name ? d->name : ""},
                        {"version", d->version ? d->version : ""},
                        {"vendor", d->vendor ? d->vendor : ""},
                        {"description", d->description ? d->description : ""},
                        {"kind", kind_name(d->kind)},
                        {"kind_version", d->kind_version},
                        {"consumes", type_names(d->consumes)},
                        {"produces", type_names(d->produces)}};
    nlohmann::json features = nlohmann::json::array(), mounts = nlohmann::json::array();
    for (const char* const* f = d->features; f && *f; ++f) {
        features.push_back(*f);
        if (std::strncmp(*f, "mount:", 6) == 0) mounts.push_back(*f + 6);
    }
    p["features"] = features;
    p["mounts"] = mounts;  // from the mount: features; empty = any mount
    p["params_schema"] = nullptr;
    if (d->params_schema_json) {
        static ParsedTextCache<nlohmann::json> schemas;  // parsed once per process
        p["params_schema"] = *schemas.get(d->params_schema_json, [](const std::string& text) {
            auto schema = nlohmann::json::parse(text, nullptr, false);
            return schema.is_discarded() ? nlohmann::json(text) : schema;
        });
    }
    return p;
}

nlohmann::json describe_loader(const Loader& loader) {
    const auto& files = loader.libraries();
    nlohmann::json j;
    j["libraries"] = nlohmann::json::array();
    for (size_t i = 0; i < files.size(); ++i) {
        const LibraryFile& l = files[i];
        if (l.refused || (!l.library && !l.manifest)) continue;  // refused, or found but not opened
        nlohmann::json ids = nlohmann::json::array();
        for (const auto& p : loader.plugins())
            if (p.library_index == i) ids.push_back(p.id);
        const std::string id = l.library ? (l.library->id ? l.library->id : "") : l.manifest->library_id;
        const std::string version =
            l.library ? (l.library->version ? l.library->version : "") : l.manifest->library_version;
        j["libraries"].push_back({{"path", l.path},
                                  {"id", id},
                                  {"version", version},
                                  {"plugins", ids},
                                  {"manifest", l.manifest ? nlohmann::json(l.manifest->path) : nlohmann::json()},
                                  {"opened", l.library != nullptr}});
    }
    j["plugins"] = nlohmann::json::array();
    for (const auto& p : loader.plugins()) {
        const LibraryFile& l = files[p.library_index];
        nlohmann::json entry = p.descriptor ? describe_plugin(p.descriptor) : l.manifest->plugins[p.manifest_entry].entry;
        entry["library"] = l.path;
        j["plugins"].push_back(entry);
    }
    j["rejected"] = nlohmann::json::array();
    for (const auto& r : loader.rejected())
        j["rejected"].push_back({{"path", r.path}, {"status", pn_status_name(r.status)}, {"reason", r.reason}});
    j["load_warnings"] = nlohmann::json::array();
    for (const auto& w : loader.warnings()) j["load_warnings"].push_back({{"path", w.path}, {"warning", w.message}});
    return j;
}

std::string Engine::describe_json() const {
    nlohmann::json j = describe_loader(*loader_);
    j["engine"] = {{"version", pn_version_string()},
                   {"abi_version", std::to_string(PN_ABI_MAJOR) + "." + std::to_string(PN_ABI_MINOR)}};
    nlohmann::json stages = nlohmann::json::array(), feedback = nlohmann::json::array();
    for (const auto& s : scheduler_->stages()) {
        stages.push_back({{"role", role_name(s->role)},
                          {"instance", s->instance_name},
                          {"plugin", s->plugin_id},
                          {"version", s->descriptor->version ? s->descriptor->version : ""},
                          {"latency_ns", s->latency_ns},
                          {"records_in", s->records_in},
                          {"records_out", s->records_out},
                          {"failures", s->failures},
                          {"resets", s->resets},
                          {"on_failure", s->on_failure == OnFailure::stop ? "stop" : "reset"}});
        if (s->call_budget_ns) {
            stages.back()["call_budget_ms"] = static_cast<double>(s->call_budget_ns) * 1e-6;
            stages.back()["over_budget"] = s->over_budget == OverBudget::stop ? "stop" : "warn";
            stages.back()["calls_over_budget"] = s->calls_over_budget;
            stages.back()["slowest_call_ms"] = static_cast<double>(s->slowest_call_ns) * 1e-6;
        }
        for (const auto& in : s->feedback) {
            const auto& from = scheduler_->stages()[in.queue - 1];
            feedback.push_back({{"from", from->instance_name}, {"to", s->instance_name}, {"types", type_names(in.mask)}});
        }
    }
    j["pipeline"] = {{"mount", config_.mount},
                     {"imu_rate_hz", config_.imu_rate_hz},
                     {"latency_ns", scheduler_->latency_ns()},
                     {"stages", stages},
                     {"feedback", feedback},
                     {"stopped", scheduler_->stopped()}};
    if (scheduler_->stopped())
        j["pipeline"]["stopped_by"] = {{"instance", scheduler_->stop_reason().where},
                                       {"reason", scheduler_->stop_reason().message}};
    uint64_t failures = 0;
    for (const auto& s : scheduler_->stages()) failures += s->failures;
    j["counters"] = {{"records_in", scheduler_->records_in()},
                     {"rejected_inputs", rejected_inputs_},
                     {"plugin_failures", failures},
                     {"outputs_queued", scheduler_->outputs().size()},
                     {"outputs_dropped", scheduler_->outputs().dropped()},
                     {"warnings", diagnostics_.warning_count()}};
    j["warnings"] = diagnostics_.warnings();
    j["origin"] = nullptr;
    if (origin_.known()) {
        const pn_geo_point_t& o = origin_.point();
        j["origin"] = {{"lat_deg", o.lat_deg}, {"lon_deg", o.lon_deg}, {"height_m", o.height_m},
                       {"from", GeoOrigin::source_name(origin_.source())}};
        if (origin_.source() == GeoOrigin::Source::plugin) j["origin"]["given_by"] = origin_.given_by();
    }
    j["map"] = nullptr;
    if (!map_.format.empty())
        j["map"] = {{"format", map_.format}, {"bytes", map_.bytes.size()}, {"from", map_.label}};
    return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

pn_status_t copy_text_out(const std::string& text, char* buffer, size_t capacity, size_t* size) {
    if (size) *size = text.size() + 1;
    if (!buffer || capacity < text.size() + 1) {
        if (buffer && capacity) buffer[0] = '\0';
        return PN_E_INVALID_ARGUMENT;
    }
    std::memcpy(buffer, text.c_str(), text.size() + 1);
    return PN_OK;
}

}  // namespace pednav::engine
