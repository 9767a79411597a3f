// SPDX-License-Identifier: Apache-2.0
// What the app sets besides samples: start point, initial attitude, geodetic
// origin, map, live params, output mask. Each is handed to the stage that
// takes it, kept, and given again to the fresh plugins after a reset.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "engine.hpp"
#include "params_schema.hpp"
#include "record_checks.hpp"

namespace pednav::engine {

namespace {

template <class Ops>
const Ops* kind_ops(const Stage& s) {
    return reinterpret_cast<const Ops*>(s.ops);
}

std::string geo_text(const pn_geo_point_t& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.8f, %.8f deg, %.2f m", p.lat_deg, p.lon_deg, p.height_m);
    return buf;
}

// "map:" + the plugin's pointer into the map: the where of a refused map.
std::string map_where(const pn_error_t& err) { return std::string("map:") + (err.where[0] ? err.where : "/"); }

}  // namespace

Stage* Engine::stage_for_role(Role role) const {
    for (const auto& s : scheduler_->stages())
        if (s->role == role) return s.get();
    return nullptr;
}

// The map matcher's load_map slot, or null; *stage = the map matcher, if any.
const pnp_map_matcher_ops_t* Engine::map_loader(Stage** stage) const {
    *stage = stage_for_role(Role::map_matcher);
    auto* ops = *stage ? kind_ops<pnp_map_matcher_ops_t>(**stage) : nullptr;
    return PNP_HAS_KIND_SLOT(ops, pnp_map_matcher_ops_t, load_map) ? ops : nullptr;
}

std::string Engine::no_map_loader_reason(const Stage* s) {
    return s ? s->instance_name + " (" + s->plugin_id + ") takes no maps"
             : "this pipeline has no map matcher to give the map to";
}

pn_status_t Engine::bad_state_after_push(const char* what, pn_error_t* err) const {
    set_error(err, PN_E_BAD_STATE, what,
              std::string(what) + " must be called before the first push (or after a reset): records have been pushed");
    return PN_E_BAD_STATE;
}

pn_status_t Engine::set_start(const double pos_enu_m[3], double heading_deg, pn_error_t* err) {
    if (pushed_) return bad_state_after_push("set_start", err);
    const double zero[3] = {0, 0, 0};
    const double* pos = pos_enu_m ? pos_enu_m : zero;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(pos[i])) {
            set_error(err, PN_E_INVALID_ARGUMENT, "start", "start position must be finite");
            return PN_E_INVALID_ARGUMENT;
        }
    if (std::isinf(heading_deg)) {
        set_error(err, PN_E_INVALID_ARGUMENT, "start", "start heading must be finite, or NaN for \"from the sensors\"");
        return PN_E_INVALID_ARGUMENT;
    }
    const double heading_rad = std::isnan(heading_deg) ? NAN : heading_deg * M_PI / 180.0;
    bool accepted = false;
    for (const auto& s : scheduler_->stages()) {
        pn_status_t st = PN_E_UNSUPPORTED;
        if (s->role == Role::position_filter) {
            auto* ops = kind_ops<pnp_position_filter_ops_t>(*s);
            if (PNP_HAS_KIND_SLOT(ops, pnp_position_filter_ops_t, set_start)) st = ops->set_start(s->self, pos, heading_rad, err);
        } else if (s->role == Role::map_matcher) {
            auto* ops = kind_ops<pnp_map_matcher_ops_t>(*s);
            if (PNP_HAS_KIND_SLOT(ops, pnp_map_matcher_ops_t, set_start)) st = ops->set_start(s->self, pos, heading_rad, err);
        } else {
            continue;
        }
        if (st == PN_OK) accepted = true;
        else if (st != PN_E_UNSUPPORTED) return st;
    }
    if (!accepted) {
        set_error(err, PN_E_UNSUPPORTED, "start", "no stage of this pipeline accepts a start point");
        return PN_E_UNSUPPORTED;
    }
    start_.set = true;
    for (int i = 0; i < 3; ++i) start_.pos_enu_m[i] = pos[i];
    start_.heading_deg = heading_deg;
    return PN_OK;
}

pn_status_t Engine::set_attitude(const double q[4], pn_error_t* err) {
    if (pushed_) return bad_state_after_push("set_attitude", err);
    if (!q || !std::isfinite(q[0] + q[1] + q[2] + q[3]) ||
        std::fabs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1.0) > kUnitQuaternionTolerance) {
        set_error(err, PN_E_INVALID_ARGUMENT, "attitude", "the attitude must be a finite unit quaternion (w, x, y, z)");
        return PN_E_INVALID_ARGUMENT;
    }
    Stage* s = stage_for_role(Role::attitude_estimator);
    auto* ops = s ? kind_ops<pnp_attitude_estimator_ops_t>(*s) : nullptr;
    if (!PNP_HAS_KIND_SLOT(ops, pnp_attitude_estimator_ops_t, set_attitude)) {
        set_error(err, PN_E_UNSUPPORTED, "attitude",
                  s ? s->instance_name + " (" + s->plugin_id + ") does not take an initial attitude"
                    : "this pipeline has no attitude estimator");
        return PN_E_UNSUPPORTED;
    }
    const pn_status_t st = ops->set_attitude(s->self, INT64_MIN, q, err);
    if (PN_FAILED(st)) return st;
    attitude_.set = true;
    for (int i = 0; i < 4; ++i) attitude_.q_enu_from_body[i] = q[i];
    return PN_OK;
}

pn_status_t Engine::set_origin(const pn_geo_point_t& p, pn_error_t* err) {
    if (pushed_) return bad_state_after_push("set_origin", err);
    if (!GeoOrigin::valid(p)) {
        set_error(err, PN_E_INVALID_ARGUMENT, "origin",
                  "the origin must be finite, latitude within 90 deg, longitude within 180 deg, height within 100 km");
        return PN_E_INVALID_ARGUMENT;
    }
    if (!origin_.set(p, GeoOrigin::Source::app)) {
        std::string from = GeoOrigin::source_name(origin_.source());
        if (origin_.source() == GeoOrigin::Source::plugin) from += std::string(" (") + origin_.given_by() + ")";
        set_error(err, PN_E_BAD_STATE, "origin",
                  "the engine already has an origin, from " + from + ": " + geo_text(origin_.point()) +
                      "; set the origin before loading a map");
        return PN_E_BAD_STATE;
    }
    return PN_OK;
}

pn_status_t Engine::load_map(const std::string& format, const void* bytes, size_t size, pn_error_t* err) {
    if (format.empty() || (!bytes && size)) {
        set_error(err, PN_E_INVALID_ARGUMENT, "map", "a map needs a format id and its bytes");
        return PN_E_INVALID_ARGUMENT;
    }
    Stage* s = nullptr;
    const pnp_map_matcher_ops_t* ops = map_loader(&s);
    if (!ops) {
        set_error(err, PN_E_UNSUPPORTED, "map", no_map_loader_reason(s));
        return PN_E_UNSUPPORTED;
    }
    pn_error_t inner{};
    inner.struct_size = sizeof inner;
    const pn_status_t st = ops->load_map(s->self, format.c_str(), bytes, size, &inner);
    if (PN_FAILED(st)) {
        set_error(err, st, map_where(inner),
                  s->instance_name + " refused the " + format + " map: " +
                      (inner.message[0] ? inner.message : "no reason given"));
        return st;
    }
    const auto* b = static_cast<const unsigned char*>(bytes);
    map_.format = format;
    map_.bytes.assign(b, b + size);
    if (map_.label.empty()) map_.label = "the app";
    return PN_OK;
}

void Engine::load_config_map() {
    Stage* s = nullptr;
    if (!map_loader(&s)) throw ConfigProblem{PN_E_INVALID_CONFIG, "/map", no_map_loader_reason(s)};
    std::ifstream in(config_.map_path, std::ios::binary);
    if (!in)
        throw ConfigProblem{PN_E_IO, "/map/path", "cannot open the map file " + config_.map_path};
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ConfigProblem{PN_E_IO, "/map/path", "cannot read the map file " + config_.map_path};
    map_.label = config_.map_path;
    pn_error_t err{};
    err.struct_size = sizeof err;
    const pn_status_t st = load_map(config_.map_format, bytes.data(), bytes.size(), &err);
    if (PN_FAILED(st)) throw ConfigProblem{st, err.where, config_.map_path + ": " + err.message};
}

pn_status_t Engine::reconfigure(const std::string& name, const std::string& params_json, pn_error_t* err) {
    Stage* s = nullptr;
    for (const auto& st : scheduler_->stages())
        if (name == role_name(st->role) || name == st->instance_name) s = st.get();
    if (!s) {
        set_error(err, PN_E_NOT_FOUND, "reconfigure", "this pipeline has no stage \"" + name + "\"");
        return PN_E_NOT_FOUND;
    }
    if (!PNP_HAS_SLOT(s->ops, pnp_node_ops_t, reconfigure)) {
        set_error(err, PN_E_UNSUPPORTED, s->instance_name, s->plugin_id + " cannot change its params live");
        return PN_E_UNSUPPORTED;
    }
    // The same checks as the config's: a JSON object, then the plugin's schema.
    const nlohmann::json doc = nlohmann::json::parse(params_json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) {
        set_error(err, PN_E_INVALID_CONFIG, "/params", "the params must be a JSON object");
        return PN_E_INVALID_CONFIG;
    }
    try {
        check_params_against_schema(*s->descriptor, StageConfig{s->role, s->plugin_id, doc.dump(), ""});
    } catch (const ConfigProblem& p) {
        set_error(err, p.status, p.where, p.message);
        return p.status;
    }
    pn_error_t inner{};
    inner.struct_size = sizeof inner;
    const pn_status_t st =
        s->ops->reconfigure(s->self, params_json.c_str(), static_cast<uint32_t>(params_json.size()), &inner);
    if (PN_FAILED(st)) {
        const std::string where = inner.where;
        set_error(err, st, "/params" + (where.rfind('/', 0) == 0 ? where : std::string()),
                  s->instance_name + " (" + s->plugin_id + ") refused the params: " +
                      (inner.message[0] ? inner.message : "no reason given"));
        return st;
    }
    return PN_OK;
}

pn_status_t Engine::set_output_mask(uint64_t mask) {
    constexpr uint64_t kOutputTypes = PN_REC_MASK(PN_REC_POSITION) | PN_REC_MASK(PN_REC_STRIDE) |
                                      PN_REC_MASK(PN_REC_STEP) | PN_REC_MASK(PN_REC_ATTITUDE) |
                                      PN_REC_MASK(PN_REC_GAIT_PHASE) | PN_REC_MASK(PN_REC_ATTITUDE_CORRECTION);
    if (mask & ~kOutputTypes) return PN_E_INVALID_ARGUMENT;
    scheduler_->set_output_mask(mask);
    return PN_OK;
}

pn_status_t Engine::reapply_settings(pn_error_t* err) {
    if (!map_.bytes.empty() || !map_.format.empty()) {
        const std::vector<unsigned char> bytes = map_.bytes;  // load_map replaces map_
        const pn_status_t st = load_map(map_.format, bytes.data(), bytes.size(), err);
        if (PN_FAILED(st)) return st;
    }
    if (start_.set) {
        const pn_status_t st = set_start(start_.pos_enu_m, start_.heading_deg, err);
        if (PN_FAILED(st)) return st;
    }
    if (attitude_.set) {
        const Attitude a = attitude_;
        const pn_status_t st = set_attitude(a.q_enu_from_body, err);
        if (PN_FAILED(st)) return st;
    }
    return PN_OK;
}

}  // namespace pednav::engine
