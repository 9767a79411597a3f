// SPDX-License-Identifier: Apache-2.0
// PEDNAV_PLUGIN_LIBRARY(lib_id, lib_version, Plugin...): generates the
// descriptors, the per-kind vtables with exception-catching trampolines, and
// the one exported entry symbol pnp_entry_v1 of a plugin library (in a static
// library built by pednav_add_plugin: pnp_entry_v1_<NAME>, see PEDNAV_SDK_ENTRY).
//
//   #include <pednav_sdk/library.hpp>
//   class MyDetector : public pednav::sdk::StepDetector { ... };
//   PEDNAV_PLUGIN_LIBRARY("org.example.steps", "1.0.0", MyDetector)
//
// Build it with pednav_add_plugin() (sdk/cmake/PednavPlugin.cmake).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>

#include "node.hpp"

namespace pednav::sdk::detail {

// Fills err with `prefix` + `message`, writing only what fits in the caller's
// struct (an older, smaller pn_error_t). Allocates nothing: it also reports
// running out of memory.
inline void fill_error(pn_error_t* err, pn_status_t code, const char* where, const char* message,
                       const char* prefix = "") noexcept {
    if (!err) return;
    const size_t size = err->struct_size < sizeof(pn_error_t) ? err->struct_size : sizeof(pn_error_t);
    if (size >= offsetof(pn_error_t, code) + sizeof err->code) err->code = code;
    if (size > offsetof(pn_error_t, where))
        std::snprintf(err->where, std::min(sizeof err->where, size - offsetof(pn_error_t, where)), "%s",
                      where ? where : "");
    if (size > offsetof(pn_error_t, message))
        std::snprintf(err->message, std::min(sizeof err->message, size - offsetof(pn_error_t, message)), "%s%s",
                      prefix, message ? message : "");
}

// Maps the exception in flight to a status and fills err.
inline pn_status_t status_from_exception(pn_error_t* err, const char* where) noexcept {
    try {
        throw;
    } catch (const ConfigError& e) {
        fill_error(err, PN_E_INVALID_CONFIG, e.where().c_str(), e.what());
        return PN_E_INVALID_CONFIG;
    } catch (const SchemaError& e) {
        fill_error(err, PN_E_INTERNAL, where, e.what());
        return PN_E_INTERNAL;
    } catch (const NumericError& e) {
        fill_error(err, PN_E_NUMERIC, where, e.what());
        return PN_E_NUMERIC;
    } catch (const InputError& e) {
        fill_error(err, PN_E_BAD_INPUT, e.where().empty() ? where : e.where().c_str(), e.what());
        return PN_E_BAD_INPUT;
    } catch (const EmitError& e) {
        fill_error(err, e.status, where, e.what());
        return e.status;
    } catch (const std::bad_alloc&) {
        fill_error(err, PN_E_OUT_OF_MEMORY, where, "out of memory");
        return PN_E_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        fill_error(err, PN_E_INTERNAL, where, e.what(), "plugin threw: ");
        return PN_E_INTERNAL;
    } catch (...) {
        fill_error(err, PN_E_INTERNAL, where, "plugin threw a non-standard exception");
        return PN_E_INTERNAL;
    }
}

// What the engine holds as `self`: the node plus what is needed to rebuild it
// on reset (a fresh object from the same params is reset by construction).
template <class T>
struct Instance {
    std::unique_ptr<T> node;
    std::string params_json;
    CreateContext context;
    const pnp_host_t* host = nullptr;
};

template <class T, class = void>
struct SchemaOf {
    static constexpr const char* value = nullptr;
};
template <class T>
struct SchemaOf<T, std::void_t<decltype(T::kParamsSchema)>> {
    static constexpr const char* value = T::kParamsSchema;
};

// T's params schema, parsed at its first create (NULL without one). A schema
// outside the subset throws SchemaError at every create.
template <class T>
const ParamsSchema* schema_of() {
    if constexpr (SchemaOf<T>::value == nullptr) {
        return nullptr;
    } else {
        static const ParamsSchema schema = ParamsSchema::parse(SchemaOf<T>::value);
        return &schema;
    }
}

template <class T>
std::unique_ptr<T> construct(const std::string& params_json, const CreateContext& context) {
    Params params(params_json, schema_of<T>());
    auto node = std::make_unique<T>(params, context);
    params.check_every_declared_read();
    params.check_no_unknown_keys();
    return node;
}

// Reads a record whose producer may be of an older minor (smaller struct):
// the missing tail reads as zeros.
template <class Record, class Fn>
inline void with_record(const pn_record_header_t* h, Fn&& fn) {
    if (h->struct_size >= sizeof(Record)) {
        fn(*reinterpret_cast<const Record*>(h));
    } else {
        Record r;
        std::memset(&r, 0, sizeof r);
        std::memcpy(&r, h, h->struct_size);
        fn(r);
    }
}

// Whether T's hook for a record can be named from here (it is public in T):
// then dispatch() calls it non-virtually.
#define PEDNAV_SDK_DIRECT_HOOK(HOOK, RECORD)                                                            \
    template <class T, class = void>                                                                  \
    struct Direct_##HOOK : std::false_type {};                                                        \
    template <class T>                                                                                \
    struct Direct_##HOOK<T, std::void_t<decltype(std::declval<T&>().T::HOOK(std::declval<const RECORD&>()))>> \
        : std::true_type {};
PEDNAV_SDK_DIRECT_HOOK(on_imu, pn_imu_t)
PEDNAV_SDK_DIRECT_HOOK(on_mag, pn_mag_t)
PEDNAV_SDK_DIRECT_HOOK(on_baro, pn_baro_t)
PEDNAV_SDK_DIRECT_HOOK(on_gnss, pn_gnss_t)
PEDNAV_SDK_DIRECT_HOOK(on_gait_phase, pn_gait_phase_t)
PEDNAV_SDK_DIRECT_HOOK(on_step, pn_step_t)
PEDNAV_SDK_DIRECT_HOOK(on_attitude, pn_attitude_t)
PEDNAV_SDK_DIRECT_HOOK(on_attitude_correction, pn_attitude_correction_t)
PEDNAV_SDK_DIRECT_HOOK(on_position, pn_position_t)
PEDNAV_SDK_DIRECT_HOOK(on_stride, pn_stride_t)
#undef PEDNAV_SDK_DIRECT_HOOK

// Calls the hook of node type T for the record. The engine's node is always
// exactly a T (the trampolines below create it), so a public hook is called
// non-virtually and can be inlined into process(); a hook T keeps private is
// called through the vtable.
#define PEDNAV_SDK_CALL_HOOK(HOOK)                                 \
    [&](const auto& r) {                                           \
        if constexpr (Direct_##HOOK<T>::value) n.T::HOOK(r);       \
        else static_cast<Node&>(n).HOOK(r);                        \
    }
template <class T>
inline void dispatch(T& n, const pn_record_header_t* h) {
    switch (h->type) {
        case PN_REC_IMU: with_record<pn_imu_t>(h, PEDNAV_SDK_CALL_HOOK(on_imu)); break;
        case PN_REC_MAG: with_record<pn_mag_t>(h, PEDNAV_SDK_CALL_HOOK(on_mag)); break;
        case PN_REC_BARO: with_record<pn_baro_t>(h, PEDNAV_SDK_CALL_HOOK(on_baro)); break;
        case PN_REC_GNSS: with_record<pn_gnss_t>(h, PEDNAV_SDK_CALL_HOOK(on_gnss)); break;
        case PN_REC_GAIT_PHASE:
            with_record<pn_gait_phase_t>(h, PEDNAV_SDK_CALL_HOOK(on_gait_phase));
            break;
        case PN_REC_STEP: with_record<pn_step_t>(h, PEDNAV_SDK_CALL_HOOK(on_step)); break;
        case PN_REC_ATTITUDE:
            with_record<pn_attitude_t>(h, PEDNAV_SDK_CALL_HOOK(on_attitude));
            break;
        case PN_REC_ATTITUDE_CORRECTION:
            with_record<pn_attitude_correction_t>(h, PEDNAV_SDK_CALL_HOOK(on_attitude_correction));
            break;
        case PN_REC_POSITION:
            with_record<pn_position_t>(h, PEDNAV_SDK_CALL_HOOK(on_position));
            break;
        case PN_REC_STRIDE: with_record<pn_stride_t>(h, PEDNAV_SDK_CALL_HOOK(on_stride)); break;
        default: break;  // a record type of a newer minor: ignore
    }
}
#undef PEDNAV_SDK_CALL_HOOK

template <class T>
struct Trampolines {
    static Instance<T>* self_of(void* self) { return static_cast<Instance<T>*>(self); }

    static pn_status_t create(const pnp_descriptor_t*, const pnp_host_t* host,
                              const pnp_create_info_t* info, void** instance,
                              pn_error_t* err) noexcept {
        if (!instance || !info) {
            fill_error(err, PN_E_INVALID_ARGUMENT, T::kId, "create: NULL argument");
            return PN_E_INVALID_ARGUMENT;
        }
        *instance = nullptr;
        try {
            auto inst = std::make_unique<Instance<T>>();
            inst->params_json.assign(info->params_json ? info->params_json : "",
                                     info->params_json ? info->params_len : 0);
            inst->context.instance_name = info->instance_name ? info->instance_name : "";
            inst->context.mount = info->mount ? info->mount : "";
            inst->context.imu_rate_hz = info->imu_rate_hz;
            inst->host = host;
            inst->node = construct<T>(inst->params_json, inst->context);
            inst->node->bind_(host, nullptr);
            *instance = inst.release();
            return PN_OK;
        } catch (...) {
            return status_from_exception(err, T::kId);
        }
    }
    static void destroy(void* self) noexcept { delete self_of(self); }
    static pn_status_t reset(void* self, pn_error_t* err) noexcept {
        auto* inst = self_of(self);
        try {
            auto fresh = construct<T>(inst->params_json, inst->context);
            fresh->bind_(inst->host, nullptr);
            inst->node = std::move(fresh);
            return PN_OK;
        } catch (...) {
            return status_from_exception(err, T::kId);
        }
    }
    static pn_status_t process(void* self, const pn_record_header_t* const* records, uint32_t count,
                               const pnp_sink_t* sink, pn_error_t* err) noexcept {
        T& n = *self_of(self)->node;
        n.bind_sink_(sink);
        try {
            for (uint32_t i = 0; i < count; ++i) dispatch<T>(n, records[i]);
        } catch (...) {
            n.bind_sink_(nullptr);
            return status_from_exception(err, T::kId);
        }
        n.bind_sink_(nullptr);
        return PN_OK;
    }
    static pn_status_t flush(void* self, const pnp_sink_t* sink, pn_error_t* err) noexcept {
        Node& n = *self_of(self)->node;
        n.bind_sink_(sink);
        try {
            n.on_flush();
        } catch (...) {
            n.bind_sink_(nullptr);
            return status_from_exception(err, T::kId);
        }
        n.bind_sink_(nullptr);
        return PN_OK;
    }
    static pn_status_t reconfigure(void* self, const char* json, uint32_t len, pn_error_t* err) noexcept {
        auto* inst = self_of(self);
        try {
            std::string text(json ? json : "", json ? len : 0);
            Params params(text, schema_of<T>());
            if (!inst->node->reconfigure(params)) {
                fill_error(err, PN_E_UNSUPPORTED, T::kId, "this plugin cannot be reconfigured live");
                return PN_E_UNSUPPORTED;
            }
            params.check_no_unknown_keys();
            inst->params_json = text;
            return PN_OK;
        } catch (...) {
            return status_from_exception(err, T::kId);
        }
    }
    // A throw here has no error to carry it: -1 is outside the range the
    // engine accepts, so it refuses the plugin at create naming it.
    static int64_t latency_ns(const void* self) noexcept {
        try {
            return static_cast<const Instance<T>*>(self)->node->latency_ns();
        } catch (...) {
            return -1;
        }
    }

    static pn_status_t unsupported(pn_error_t* err, const char* what) {
        fill_error(err, PN_E_UNSUPPORTED, T::kId, " is not supported by this plugin", what);
        return PN_E_UNSUPPORTED;
    }
    static pn_status_t set_start(void* self, const double pos[3], double heading, pn_error_t* err) noexcept {
        try {
            return self_of(self)->node->set_start(pos, heading) ? PN_OK : unsupported(err, "set_start");
        } catch (...) {
            return status_from_exception(err, T::kId);
        }
    }
    static pn_status_t set_attitude(void* self, int64_t t_ns, const double q[4], pn_error_t* err) noexcept {
        try {
            return self_of(self)->node->set_attitude(t_ns, q) ? PN_OK : unsupported(err, "set_attitude");
        } catch (...) {
            return status_from_exception(err, T::kId);
        }
    }
    static pn_status_t load_map(void* self, const char* format, const void* bytes, size_t size,
                                pn_error_t* err) noexcept {
        try {
            return self_of(self)->node->load_map(format ? format : "", bytes, size)
                       ? PN_OK
                       : unsupported(err, "load_map");
        } catch (...) {
            return status_from_exception(err, T::kId);
        }
    }

    static constexpr pnp_node_ops_t node_ops() {
        return pnp_node_ops_t{0,      0,            &destroy,    &reset, &process,
                              &flush, &reconfigure, &latency_ns, nullptr};
    }
};

// Per-kind vtable for T.
template <class T, pnp_kind_t Kind = T::kKind>
struct OpsFor;
template <class T>
struct OpsFor<T, PNP_KIND_STEP_DETECTOR> {
    static constexpr pnp_step_detector_ops_t make() {
        pnp_step_detector_ops_t o{Trampolines<T>::node_ops()};
        o.node.struct_size = sizeof(o);
        return o;
    }
};
template <class T>
struct OpsFor<T, PNP_KIND_ATTITUDE_ESTIMATOR> {
    static constexpr pnp_attitude_estimator_ops_t make() {
        pnp_attitude_estimator_ops_t o{Trampolines<T>::node_ops(), &Trampolines<T>::set_attitude};
        o.node.struct_size = sizeof(o);
        return o;
    }
};
template <class T>
struct OpsFor<T, PNP_KIND_POSITION_FILTER> {
    static constexpr pnp_position_filter_ops_t make() {
        pnp_position_filter_ops_t o{Trampolines<T>::node_ops(), &Trampolines<T>::set_start};
        o.node.struct_size = sizeof(o);
        return o;
    }
};
template <class T>
struct OpsFor<T, PNP_KIND_MAP_MATCHER> {
    static constexpr pnp_map_matcher_ops_t make() {
        pnp_map_matcher_ops_t o{Trampolines<T>::node_ops(), &Trampolines<T>::load_map,
                                &Trampolines<T>::set_start};
        o.node.struct_size = sizeof(o);
        return o;
    }
};

template <class T, class = void>
struct FeaturesOf {
    static constexpr const char* const* value = nullptr;
};
template <class T>
struct FeaturesOf<T, std::void_t<decltype(T::kFeatures)>> {
    static constexpr const char* const* value = T::kFeatures;
};
template <class T, class = void>
struct VendorOf {
    static constexpr const char* value = "";
};
template <class T>
struct VendorOf<T, std::void_t<decltype(T::kVendor)>> {
    static constexpr const char* value = T::kVendor;
};

template <class T>
struct DescriptorOf {
    static constexpr auto ops = OpsFor<T>::make();
    static constexpr pnp_descriptor_t value{PN_ABI_VERSION,
                                            sizeof(pnp_descriptor_t),
                                            T::kId,
                                            T::kName,
                                            T::kVersion,
                                            VendorOf<T>::value,
                                            T::kDescription,
                                            FeaturesOf<T>::value,
                                            SchemaOf<T>::value,
                                            T::kKind,
                                            1,
                                            T::kConsumes,
                                            T::kProduces,
                                            &Trampolines<T>::create,
                                            &ops.node};
};

template <class... Ts>
struct LibraryOf {
    static constexpr const pnp_descriptor_t* plugins[] = {&DescriptorOf<Ts>::value...};
    static constexpr uint32_t count = sizeof...(Ts);
};

}  // namespace pednav::sdk::detail

// The entry function: pnp_entry_v1, exported, in a plugin library; in a static
// library pnp_entry_v1_<name>, where pednav_add_plugin(NAME <name>) defines
// PEDNAV_PLUGIN_STATIC_NAME=<name>, so that several plugin libraries link into
// one binary (iOS) and the app passes pnp_entry_v1_<name>() to the engine.
#define PEDNAV_SDK_CAT_(a, b) a##b
#define PEDNAV_SDK_CAT(a, b) PEDNAV_SDK_CAT_(a, b)
#if defined(PEDNAV_PLUGIN_STATIC_NAME)
#define PEDNAV_SDK_ENTRY PEDNAV_SDK_CAT(pnp_entry_v1_, PEDNAV_PLUGIN_STATIC_NAME)
#define PEDNAV_SDK_ENTRY_EXPORT
#elif defined(_WIN32)
#define PEDNAV_SDK_ENTRY pnp_entry_v1
#define PEDNAV_SDK_ENTRY_EXPORT __declspec(dllexport)
#else
#define PEDNAV_SDK_ENTRY pnp_entry_v1
#define PEDNAV_SDK_ENTRY_EXPORT __attribute__((visibility("default")))
#endif

#define PEDNAV_PLUGIN_LIBRARY(LIB_ID, LIB_VERSION, ...)                                        \
    extern "C" PEDNAV_SDK_ENTRY_EXPORT const pnp_library_t* PEDNAV_SDK_ENTRY(void) noexcept {  \
        using Lib_ = ::pednav::sdk::detail::LibraryOf<__VA_ARGS__>;                            \
        static constexpr pnp_library_t library{PN_ABI_VERSION,                                 \
                                               sizeof(pnp_library_t),                          \
                                               LIB_ID,                                         \
                                               LIB_VERSION,                                    \
                                               nullptr,                                        \
                                               nullptr,                                        \
                                               Lib_::count,                                    \
                                               0,                                              \
                                               Lib_::plugins};                                 \
        return &library;                                                                       \
    }
