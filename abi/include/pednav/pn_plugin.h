/*
 * pednav stable C ABI, part 2 of 3: what a plugin library exports.
 *
 * A plugin library exports exactly one symbol, the entry function
 *     const pnp_library_t *pnp_entry_v1(void);
 * whose name carries the ABI major. It returns a pointer to static constant
 * data and does nothing else (no allocation, no threads, no I/O), so the engine
 * can inspect a library before running any of its code.
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

/* What the engine gives each instance. One per instance, valid until destroy. */
typedef struct pnp_host_t {
    uint32_t abi_version; /* PN_ABI_VERSION of the engine */
    uint32_t struct_size;
    void *host_data; /* engine's own; do not touch */
    /* [thread-safe] Write one log line attributed to this instance. msg is
     * borrowed for the call. */
    void (*log)(const struct pnp_host_t *host, pnp_log_level_t level, const char *msg)PNP_NOEXCEPT;
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
    /* [instance] Apply new params without losing state. Optional. */
    pn_status_t (*reconfigure)(void *self, const char *params_json, uint32_t params_len,
                               pn_error_t *err)PNP_NOEXCEPT;
    /* [instance] Fixed look-ahead in ns: every output about time t is emitted by
     * the time the instance has consumed input up to t + latency. The scheduler
     * delays the other streams by the same amount so downstream nodes see
     * inputs and decisions aligned. Optional (NULL = 0). Must not change
     * between reset and destroy. */
    int64_t (*latency_ns)(const void *self)PNP_NOEXCEPT;
    /* [thread-safe] Optional extension by id ("vendor.name/rev"), NULL if none. */
    const void *(*get_extension)(const void *self, const char *id)PNP_NOEXCEPT;
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
    /* [instance] Force the attitude (e.g. from a user-given heading). */
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
    /* [instance] Load a map: format id ("pednav.map/1" = GeoJSON walls/zones),
     * bytes borrowed for the call. */
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
    const char *const *features; /* NULL-terminated tags: "mount:foot", "needs:mag" */
    const char *params_schema_json; /* JSON Schema of params, may be NULL */
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
