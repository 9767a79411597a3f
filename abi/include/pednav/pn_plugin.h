/* SPDX-License-Identifier: Apache-2.0 */
/*
 * pednav stable C ABI, part 2 of 3: what a plugin library exports.
 *
 * A plugin library exports exactly one symbol, the entry function
 *     const pnp_library_t *pnp_entry_v1(void);
 * whose name carries the ABI major. It returns a pointer to static constant
 * data and does nothing else (no allocation, no threads, no I/O). Opening a
 * library runs its static initializers, so the engine decides which libraries
 * to open from the manifests written beside them at build time, and opens only
 * those whose plugins the configured pipeline uses (docs/loading.md).
 *
 * Growable structs begin with {abi_version, struct_size} or {struct_size}. A
 * reader uses the prefix it knows; slots appended by later minors are tested
 * with PNP_HAS_SLOT. Minimum sizes (PNP_*_MIN_SIZE) are pinned at 1.0.
 *
 * Thread tags on every slot:
 *   [thread-safe] may be called from any thread, concurrently;
 *   [instance]    the engine never overlaps two calls on one instance, but
 *                 consecutive calls may come from different threads;
 *   [load]        serialized with every other call into the same library.
 *
 * Ownership: input records are borrowed for the duration of the call; output
 * records are handed to the sink, which copies them before it returns.
 * No C++ type, exception or heap pointer crosses this boundary.
 *
 * Exceptions: no slot may throw. In C++17 every slot is a noexcept function
 * pointer; an exception leaving one calls std::terminate, or, where the
 * plugin cast a throwing function to the slot type, unwinds through engine
 * frames compiled on the promise that nothing throws: undefined behaviour
 * that no engine can catch portably. Plugins built with the SDK
 * (pednav_sdk/library.hpp) are safe: its trampolines catch every exception
 * in every slot and return a status with the message (PN_E_INTERNAL,
 * "plugin threw: what()"). A raw C++ plugin must do the same itself;
 * `pednav validate` runs a plugin in a child process to find one that
 * does not.
 *
 * Failures: a failed process or flush, and an output the engine refuses
 * (non-finite, a covariance not symmetric positive semi-definite, time going
 * backwards, an undeclared type), are reported to the app naming the
 * instance and plugin id; the stage's config then resets the instance or
 * stops the pipeline ("on_failure"), and may bound each call's time
 * ("call_budget_ms"); see docs/config.md.
 *
 * Library data: the pnp_library_t, its plugins array (plugin_count entries),
 * the descriptors, vtables and ids must be static data of the library file
 * itself; the loader checks they lie in its loaded segments before reading
 * them and refuses the library otherwise.
 */
#ifndef PEDNAV_PN_PLUGIN_H
#define PEDNAV_PN_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#include "pn_types.h"

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__cplusplus) && __cplusplus >= 201703L
#define PNP_NOEXCEPT noexcept
#else
#define PNP_NOEXCEPT
#endif

/* Name of the entry symbol of this ABI major. */
#define PNP_ENTRY_SYMBOL "pnp_entry_v1"

/* True when a struct of the given struct_size holds `field` and the slot is set. */
#define PNP_HAS_SLOT(ptr, type, field)                                        \
    ((ptr) != NULL && (ptr)->struct_size >= offsetof(type, field) + sizeof((ptr)->field) && \
     (ptr)->field != NULL)
/* The same for the kind-specific slots of a kind vtable (pnp_*_ops_t), whose
 * struct_size lives in its node prefix. */
#define PNP_HAS_KIND_SLOT(ptr, type, field)                                   \
    ((ptr) != NULL && (ptr)->node.struct_size >= offsetof(type, field) + sizeof((ptr)->field) && \
     (ptr)->field != NULL)

/* Plugin kinds. */
typedef int32_t pnp_kind_t;
enum {
    PNP_KIND_STEP_DETECTOR = 1,      /* IMU -> GAIT_PHASE and/or STEP */
    PNP_KIND_ATTITUDE_ESTIMATOR = 2, /* IMU (+MAG, ATTITUDE_CORRECTION) -> ATTITUDE */
    PNP_KIND_POSITION_FILTER = 3,    /* IMU, STEP, ATTITUDE, GNSS, BARO -> POSITION, STRIDE */
    PNP_KIND_MAP_MATCHER = 4         /* POSITION, STRIDE, BARO -> POSITION (with floor) */
};

/* Log levels for pnp_host_t.log. */
typedef int32_t pnp_log_level_t;
enum { PNP_LOG_DEBUG = 0, PNP_LOG_INFO = 1, PNP_LOG_WARN = 2, PNP_LOG_ERROR = 3 };

/* ------------------------------------------------------------------ host */

/* What the engine gives each instance (valid until its destroy) and each
 * library's init (valid until the library is unloaded). Slots after `log` were
 * added in 1.1: test them with PNP_HAS_SLOT, an engine of 1.0 lacks them. */
typedef struct pnp_host_t {
    uint32_t abi_version; /* PN_ABI_VERSION of the engine */
    uint32_t struct_size;
    void *host_data; /* engine's own; do not touch */
    /* [thread-safe] Write one log line attributed to this instance (or, from
     * init, to the library). msg is borrowed for the call. Lines at
     * PNP_LOG_WARN and above are also kept in the engine's description. */
    void (*log)(const struct pnp_host_t *host, pnp_log_level_t level, const char *msg)PNP_NOEXCEPT;
    /* [instance] 1.1. The engine's geodetic origin, the WGS-84 point at ENU
     * (0, 0, 0): PN_OK with *origin filled, or PN_NO_DATA while the engine has
     * none. An engine without one may get it later (from the first good GNSS
     * fix), never changes it once it has one, and forgets a fix-derived origin
     * on reset. Call it from within a call the engine made into the instance. */
    pn_status_t (*get_origin)(const struct pnp_host_t *host, pn_geo_point_t *origin)PNP_NOEXCEPT;
    /* [instance] 1.1. Offers an origin, e.g. the one a map matcher's map
     * declares: PN_OK when the engine had none and takes it, PN_E_BAD_STATE
     * when it already has one (read it with get_origin and use that),
     * PN_E_INVALID_ARGUMENT when the point is not finite or out of range. */
    pn_status_t (*offer_origin)(const struct pnp_host_t *host, const pn_geo_point_t *origin)PNP_NOEXCEPT;
} pnp_host_t;

/* Where a plugin puts its outputs during process/flush. */
typedef struct pnp_sink_t {
    void *sink_data; /* engine's own */
    /* [instance] Copy one record out. The record is borrowed for the call and
     * must be at most PN_RECORD_MAX_SIZE bytes with a correct struct_size.
     * Returns PN_OK, or a failure if the record breaks the contract (unknown
     * type, time going backwards, non-finite value); the plugin should then
     * return that status. */
    pn_status_t (*emit)(const struct pnp_sink_t *sink, const pn_record_header_t *record)PNP_NOEXCEPT;
} pnp_sink_t;

/* What create() receives. Strings are borrowed for the call. */
typedef struct pnp_create_info_t {
    uint32_t abi_version;
    uint32_t struct_size;
    const char *params_json;   /* the instance's "params" object, compact UTF-8 JSON, NUL-terminated */
    uint32_t params_len;       /* bytes, without the NUL */
    uint32_t reserved;
    const char *instance_name; /* e.g. "foot/step_detector" */
    const char *mount;         /* "foot", "chest" or "waist" */
    double imu_rate_hz;        /* nominal IMU rate, 0 when unknown */
} pnp_create_info_t;

/* ----------------------------------------------------------------- vtables */

/* The prefix shared by every kind's vtable. */
typedef struct pnp_node_ops_t {
    uint32_t struct_size;
    uint32_t reserved;
    /* [instance] Free everything the instance owns. Required. */
    void (*destroy)(void *self)PNP_NOEXCEPT;
    /* [instance] Back to the state right after create. Required. */
    pn_status_t (*reset)(void *self, pn_error_t *err)PNP_NOEXCEPT;
    /* [instance] Consume `count` records in time order (borrowed for the call),
     * emit outputs through `sink`. Required. */
    pn_status_t (*process)(void *self, const pn_record_header_t *const *records, uint32_t count,
                           const pnp_sink_t *sink, pn_error_t *err)PNP_NOEXCEPT;
    /* [instance] End of stream: emit what is still pending. Optional. */
    pn_status_t (*flush)(void *self, const pnp_sink_t *sink, pn_error_t *err)PNP_NOEXCEPT;
    /* [instance] Apply new params (the whole "params" object, compact UTF-8
     * JSON, NUL-terminated; borrowed for the call) without losing state; they
     * apply from the next record processed and survive reset. Called by
     * pn_engine_reconfigure after the engine has checked them against the
     * params schema. Return PN_E_UNSUPPORTED when the new values need a new
     * instance (the old ones stay in force). Optional (NULL = unsupported). */
    pn_status_t (*reconfigure)(void *self, const char *params_json, uint32_t params_len,
                               pn_error_t *err)PNP_NOEXCEPT;
    /* [instance] Fixed look-ahead in ns: every output about time t is emitted by
     * the time the instance has consumed input up to t + latency. The scheduler
     * delays the other streams by the same amount so downstream nodes see
     * inputs and decisions aligned. Optional (NULL = 0). Must not change
     * between reset and destroy. */
    int64_t (*latency_ns)(const void *self)PNP_NOEXCEPT;
    /* Reserved. 1.0 declared an extension query here that no engine ever
     * called; it was withdrawn in 1.1 before anything relied on it. Leave NULL:
     * engines of 1.x never read this slot. */
    const void *reserved_slot;
} pnp_node_ops_t;
/* destroy, reset and process are required; the slots after them are optional
 * tail slots (test with PNP_HAS_SLOT), so this minimum never grows. */
#define PNP_NODE_OPS_MIN_SIZE (offsetof(pnp_node_ops_t, process) + sizeof(void *))

/* Kind-specific control slots follow the prefix. All optional. */
typedef struct pnp_step_detector_ops_t {
    pnp_node_ops_t node;
} pnp_step_detector_ops_t;

typedef struct pnp_attitude_estimator_ops_t {
    pnp_node_ops_t node;
    /* [instance] Start from this attitude instead of the estimator's own
     * alignment: called before the first record (and again after each reset)
     * when the app gave one with pn_engine_set_attitude. t_ns is the time it
     * holds at, INT64_MIN for "the first sample". q is a unit quaternion,
     * Hamilton, w first. Return PN_E_UNSUPPORTED if the estimator cannot
     * take one. */
    pn_status_t (*set_attitude)(void *self, int64_t t_ns, const double q_enu_from_body[4],
                                pn_error_t *err)PNP_NOEXCEPT;
} pnp_attitude_estimator_ops_t;

typedef struct pnp_position_filter_ops_t {
    pnp_node_ops_t node;
    /* [instance] Set the start point (ENU metres) and heading (rad, clockwise
     * from north; NaN = leave to the filter's own alignment). */
    pn_status_t (*set_start)(void *self, const double pos_enu_m[3], double heading_rad,
                             pn_error_t *err)PNP_NOEXCEPT;
} pnp_position_filter_ops_t;

typedef struct pnp_map_matcher_ops_t {
    pnp_node_ops_t node;
    /* [instance] Load a map, replacing any map loaded before: format id
     * ("pednav.map/1" = GeoJSON, docs/maps.md), bytes borrowed for the call
     * (not NUL-terminated). Called when the app gives a map (the config's
     * "map" at create, pn_engine_load_map between records) and again after
     * each reset with the last map given. On failure fill err.where with a JSON pointer into the
     * map document naming the feature at fault ("/features/12/geometry") and
     * keep the previous map. A map in WGS-84 needs the geodetic origin: read it
     * with host->get_origin, or offer the map's own with host->offer_origin. */
    pn_status_t (*load_map)(void *self, const char *format, const void *bytes, size_t size,
                            pn_error_t *err)PNP_NOEXCEPT;
    /* [instance] Same meaning as for position filters. */
    pn_status_t (*set_start)(void *self, const double pos_enu_m[3], double heading_rad,
                             pn_error_t *err)PNP_NOEXCEPT;
} pnp_map_matcher_ops_t;

/* ---------------------------------------------------------- descriptors */

typedef struct pnp_descriptor_t {
    uint32_t abi_version;
    uint32_t struct_size;
    const char *id;          /* reverse-DNS, what configs name; fixed forever */
    const char *name;
    const char *version;     /* semver of the plugin */
    const char *vendor;
    const char *description;
    /* NULL-terminated tags. "mount:<m>": a mount the plugin is made for
     * (foot, chest, handheld, waist). "needs:<type>" (record type names as in
     * pn_engine_describe: gait_phase, attitude, step, position, stride, ...):
     * a type the plugin cannot work without; an engine whose earlier stages
     * produce no such record is refused at create (app input types are not
     * checked: the app may push them). "uses:<type>": used when present. */
    const char *const *features;
    /* The params as a JSON Schema in the subset of docs/parameters.md (per key:
     * type, default, range, unit, meaning), the one place a plugin's defaults
     * are written; the engine checks configs against it before create. NULL =
     * the plugin checks its params alone. */
    const char *params_schema_json;
    pnp_kind_t kind;
    uint32_t kind_version;   /* semantics of the kind contract, 1 */
    uint64_t consumes;       /* PN_REC_MASK bits */
    uint64_t produces;       /* PN_REC_MASK bits */
    /* [thread-safe] Create an instance. On failure return a status, leave
     * *instance NULL and fill err (where = the params key at fault). */
    pn_status_t (*create)(const struct pnp_descriptor_t *desc, const pnp_host_t *host,
                          const pnp_create_info_t *info, void **instance,
                          pn_error_t *err)PNP_NOEXCEPT;
    /* Points to the kind's vtable (pnp_*_ops_t), which begins with pnp_node_ops_t. */
    const pnp_node_ops_t *ops;
} pnp_descriptor_t;
#define PNP_DESCRIPTOR_MIN_SIZE (offsetof(pnp_descriptor_t, ops) + sizeof(void *))

typedef struct pnp_library_t {
    uint32_t abi_version;
    uint32_t struct_size;
    const char *id;      /* library id, reverse-DNS */
    const char *version; /* semver */
    /* [load] Optional. Called once before the first create of any plugin of
     * this library; may refuse an engine too old for it (PN_E_ABI_MISMATCH). */
    pn_status_t (*init)(const pnp_host_t *host, pn_error_t *err)PNP_NOEXCEPT;
    /* [load] Optional. Called once after the last instance is destroyed. */
    void (*deinit)(void)PNP_NOEXCEPT;
    uint32_t plugin_count;
    uint32_t reserved;
    const pnp_descriptor_t *const *plugins;
} pnp_library_t;
#define PNP_LIBRARY_MIN_SIZE (offsetof(pnp_library_t, plugins) + sizeof(void *))

/* The entry function type. */
typedef const pnp_library_t *(*pnp_entry_fn)(void);

#ifdef __cplusplus
}
#endif

#endif /* PEDNAV_PN_PLUGIN_H */
