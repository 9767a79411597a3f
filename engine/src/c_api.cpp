// SPDX-License-Identifier: Apache-2.0
// pn_engine.h implemented over engine::Engine. No exception leaves this file.
#include <cstring>
#include <new>
#include <string>

#include <pednav/pn_engine.h>

#include "describe.hpp"
#include "engine.hpp"
#include "geo_frame.hpp"

using pednav::engine::ConfigProblem;
using pednav::engine::Engine;
using pednav::engine::set_error;

struct pn_engine_t {
    Engine engine;
    explicit pn_engine_t(const pn_engine_create_info_t& info) : engine(info) {}
};

#ifndef PEDNAV_VERSION_STRING
#define PEDNAV_VERSION_STRING "0.0.0"
#endif

extern "C" {

uint32_t pn_abi_version(void) { return PN_ABI_VERSION; }
const char* pn_version_string(void) { return PEDNAV_VERSION_STRING; }

const char* pn_status_name(pn_status_t s) {
    switch (s) {
        case PN_OK: return "PN_OK";
        case PN_NO_DATA: return "PN_NO_DATA";
        case PN_E_INVALID_ARGUMENT: return "PN_E_INVALID_ARGUMENT";
        case PN_E_INVALID_CONFIG: return "PN_E_INVALID_CONFIG";
        case PN_E_UNSUPPORTED: return "PN_E_UNSUPPORTED";
        case PN_E_ABI_MISMATCH: return "PN_E_ABI_MISMATCH";
        case PN_E_NOT_FOUND: return "PN_E_NOT_FOUND";
        case PN_E_BAD_STATE: return "PN_E_BAD_STATE";
        case PN_E_OUT_OF_ORDER: return "PN_E_OUT_OF_ORDER";
        case PN_E_NUMERIC: return "PN_E_NUMERIC";
        case PN_E_OUT_OF_MEMORY: return "PN_E_OUT_OF_MEMORY";
        case PN_E_IO: return "PN_E_IO";
        case PN_E_INTERNAL: return "PN_E_INTERNAL";
        case PN_E_BAD_INPUT: return "PN_E_BAD_INPUT";
        default: return s < 0 ? "PN_E_UNKNOWN" : "PN_OK_WITH_NOTE";
    }
}

pn_status_t pn_engine_create(const pn_engine_create_info_t* info, pn_engine_t** engine, pn_error_t* err) {
    if (!engine) {
        set_error(err, PN_E_INVALID_ARGUMENT, "engine", "engine out-pointer is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    *engine = nullptr;
    if (!info || info->struct_size < offsetof(pn_engine_create_info_t, log) || !info->config_json) {
        set_error(err, PN_E_INVALID_ARGUMENT, "create_info", "create info is NULL, too small, or has no config_json");
        return PN_E_INVALID_ARGUMENT;
    }
    if (PN_ABI_VERSION_MAJOR(info->abi_version) != PN_ABI_MAJOR) {
        set_error(err, PN_E_ABI_MISMATCH, "create_info", "the app was built against another ABI major");
        return PN_E_ABI_MISMATCH;
    }
    // Copy into a full-size struct so an app built against an older minor works.
    pn_engine_create_info_t full{};
    std::memcpy(&full, info, std::min<size_t>(info->struct_size, sizeof full));
    try {
        *engine = new pn_engine_t(full);
        return PN_OK;
    } catch (const ConfigProblem& p) {
        set_error(err, p.status, p.where, p.message);
        return p.status;
    } catch (const std::bad_alloc&) {
        set_error(err, PN_E_OUT_OF_MEMORY, "engine", "out of memory");
        return PN_E_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        set_error(err, PN_E_INTERNAL, "engine", e.what());
        return PN_E_INTERNAL;
    }
}

void pn_engine_destroy(pn_engine_t* engine) { delete engine; }

pn_status_t pn_engine_push_imu(pn_engine_t* engine, const pn_imu_t* samples, size_t count, size_t stride_bytes,
                               pn_error_t* err) {
    if (!engine || (count && !samples)) {
        set_error(err, PN_E_INVALID_ARGUMENT, "push_imu", "engine or samples is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    // No IMU record is shorter than its 1.0 size, so neither can the stride be
    // (and every sample's header then lies inside the app's array).
    if (count && stride_bytes < PN_IMU_MIN_SIZE) {
        set_error(err, PN_E_INVALID_ARGUMENT, "push_imu",
                  "stride_bytes " + std::to_string(stride_bytes) + " is smaller than an IMU record (" +
                      std::to_string(PN_IMU_MIN_SIZE) + " bytes)");
        return PN_E_INVALID_ARGUMENT;
    }
    const unsigned char* p = reinterpret_cast<const unsigned char*>(samples);
    for (size_t i = 0; i < count; ++i) {
        const auto* h = reinterpret_cast<const pn_record_header_t*>(p + i * stride_bytes);
        if (h->type != PN_REC_IMU) {
            set_error(err, PN_E_INVALID_ARGUMENT, "push_imu", "sample is not an IMU record", static_cast<int32_t>(i));
            return PN_E_INVALID_ARGUMENT;
        }
        // The engine copies struct_size bytes: never more than the sample's slot in the array.
        if (h->struct_size > stride_bytes) {
            set_error(err, PN_E_INVALID_ARGUMENT, "push_imu",
                      "sample " + std::to_string(i) + " has struct_size " + std::to_string(h->struct_size) +
                          ", larger than stride_bytes " + std::to_string(stride_bytes),
                      static_cast<int32_t>(i));
            return PN_E_INVALID_ARGUMENT;
        }
        try {
            const pn_status_t s = engine->engine.push(h, err);
            if (PN_FAILED(s)) {
                if (err && err->struct_size >= sizeof(pn_error_t)) err->detail = static_cast<int32_t>(i);
                return s;
            }
        } catch (const std::bad_alloc&) {
            set_error(err, PN_E_OUT_OF_MEMORY, "engine", "out of memory", static_cast<int32_t>(i));
            return PN_E_OUT_OF_MEMORY;
        } catch (const std::exception& e) {
            set_error(err, PN_E_INTERNAL, "engine", e.what(), static_cast<int32_t>(i));
            return PN_E_INTERNAL;
        }
    }
    return PN_OK;
}

pn_status_t pn_engine_push(pn_engine_t* engine, const pn_record_header_t* record, pn_error_t* err) {
    if (!engine) {
        set_error(err, PN_E_INVALID_ARGUMENT, "push", "engine is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    try {
        return engine->engine.push(record, err);
    } catch (const std::bad_alloc&) {
        set_error(err, PN_E_OUT_OF_MEMORY, "engine", "out of memory");
        return PN_E_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        set_error(err, PN_E_INTERNAL, "engine", e.what());
        return PN_E_INTERNAL;
    }
}

pn_status_t pn_engine_push_records(pn_engine_t* engine, const pn_record_header_t* const* records, size_t count,
                                   pn_error_t* err) {
    if (!engine || (count && !records)) {
        set_error(err, PN_E_INVALID_ARGUMENT, "push_records", "engine or records is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    for (size_t i = 0; i < count; ++i) {
        const pn_status_t s = pn_engine_push(engine, records[i], err);
        if (PN_FAILED(s)) {
            if (err && err->struct_size >= sizeof(pn_error_t)) err->detail = static_cast<int32_t>(i);
            return s;
        }
    }
    return PN_OK;
}

#define PN_GUARDED(name, call)                                             \
    if (!engine) {                                                         \
        set_error(err, PN_E_INVALID_ARGUMENT, name, "engine is NULL");     \
        return PN_E_INVALID_ARGUMENT;                                      \
    }                                                                      \
    try {                                                                  \
        return call;                                                       \
    } catch (const std::bad_alloc&) {                                      \
        set_error(err, PN_E_OUT_OF_MEMORY, "engine", "out of memory");     \
        return PN_E_OUT_OF_MEMORY;                                         \
    } catch (const std::exception& e) {                                    \
        set_error(err, PN_E_INTERNAL, "engine", e.what());                 \
        return PN_E_INTERNAL;                                              \
    }

pn_status_t pn_engine_flush(pn_engine_t* engine, pn_error_t* err) { PN_GUARDED("flush", engine->engine.flush(err)) }
pn_status_t pn_engine_reset(pn_engine_t* engine, pn_error_t* err) { PN_GUARDED("reset", engine->engine.reset(err)) }
pn_status_t pn_engine_set_start(pn_engine_t* engine, const double pos_enu_m[3], double heading_deg, pn_error_t* err) {
    PN_GUARDED("set_start", engine->engine.set_start(pos_enu_m, heading_deg, err))
}
pn_status_t pn_engine_set_attitude(pn_engine_t* engine, const double q_enu_from_body[4], pn_error_t* err) {
    PN_GUARDED("set_attitude", engine->engine.set_attitude(q_enu_from_body, err))
}
pn_status_t pn_engine_set_origin(pn_engine_t* engine, const pn_geo_point_t* origin, pn_error_t* err) {
    if (!origin) {
        set_error(err, PN_E_INVALID_ARGUMENT, "origin", "origin is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    PN_GUARDED("set_origin", engine->engine.set_origin(*origin, err))
}
pn_status_t pn_engine_load_map(pn_engine_t* engine, const char* format, const void* bytes, size_t size,
                               pn_error_t* err) {
    PN_GUARDED("load_map", engine->engine.load_map(format ? format : "", bytes, size, err))
}
pn_status_t pn_engine_reconfigure(pn_engine_t* engine, const char* stage, const char* params_json, size_t params_len,
                                  pn_error_t* err) {
    if (!stage || !params_json) {
        set_error(err, PN_E_INVALID_ARGUMENT, "reconfigure", "stage or params_json is NULL");
        return PN_E_INVALID_ARGUMENT;
    }
    PN_GUARDED("reconfigure",
               engine->engine.reconfigure(stage, params_len ? std::string(params_json, params_len) : std::string(params_json),
                                          err))
}

pn_status_t pn_engine_get_origin(const pn_engine_t* engine, pn_geo_point_t* origin) {
    if (!engine || !origin) return PN_E_INVALID_ARGUMENT;
    const auto& o = engine->engine.origin();
    if (!o.known()) return PN_NO_DATA;
    *origin = o.point();
    return PN_OK;
}

pn_status_t pn_engine_geo_from_enu(const pn_engine_t* engine, const double pos_enu_m[3], pn_geo_point_t* out) {
    if (!engine || !pos_enu_m || !out) return PN_E_INVALID_ARGUMENT;
    const auto& o = engine->engine.origin();
    if (!o.known()) return PN_NO_DATA;
    *out = pednav::engine::geo_from_enu(o.point(), pos_enu_m);
    return PN_OK;
}

pn_status_t pn_engine_enu_from_geo(const pn_engine_t* engine, const pn_geo_point_t* point, double pos_enu_m[3]) {
    if (!engine || !point || !pos_enu_m) return PN_E_INVALID_ARGUMENT;
    const auto& o = engine->engine.origin();
    if (!o.known()) return PN_NO_DATA;
    pednav::engine::enu_from_geo(o.point(), *point, pos_enu_m);
    return PN_OK;
}

pn_status_t pn_engine_poll(pn_engine_t* engine, pn_output_t* out) {
    if (!engine || !out) return PN_E_INVALID_ARGUMENT;
    return engine->engine.scheduler().outputs().pop(out) ? PN_OK : PN_NO_DATA;
}

pn_status_t pn_engine_poll_many(pn_engine_t* engine, pn_output_t* out, size_t capacity, size_t* count) {
    if (count) *count = 0;
    if (!engine || !count || (capacity && !out)) return PN_E_INVALID_ARGUMENT;
    auto& queue = engine->engine.scheduler().outputs();
    size_t n = 0;
    while (n < capacity && queue.pop(&out[n])) ++n;
    *count = n;
    return PN_OK;
}

pn_status_t pn_engine_get_latest(pn_engine_t* engine, pn_record_type_t type, pn_output_t* out) {
    if (!engine || !out) return PN_E_INVALID_ARGUMENT;
    return engine->engine.scheduler().outputs().latest(type, out) ? PN_OK : PN_NO_DATA;
}

pn_status_t pn_engine_set_output_mask(pn_engine_t* engine, uint64_t mask) {
    if (!engine) return PN_E_INVALID_ARGUMENT;
    return engine->engine.set_output_mask(mask);
}

int64_t pn_engine_latency_ns(const pn_engine_t* engine) {
    return engine ? engine->engine.scheduler().latency_ns() : 0;
}

pn_status_t pn_engine_describe(const pn_engine_t* engine, char* buffer, size_t capacity, size_t* size) {
    if (!engine) return PN_E_INVALID_ARGUMENT;
    std::string text;
    try {
        text = engine->engine.describe_json();
    } catch (const std::exception&) {
        return PN_E_INTERNAL;
    }
    return pednav::engine::copy_text_out(text, buffer, capacity, size);
}

}  // extern "C"
